package eu.brain.iot.bms.monitoring.api;

import java.util.List;

import org.osgi.annotation.versioning.ProviderType;

/** Live state of the Behaviour Management Service, registered as a service by it. Each call returns a fresh copy. */
@ProviderType
public interface BehaviourManagerStatistics {

    /** @return every event type the BMS is deciding about (searching, installing, retrying, or not searched again
     *         for a while), oldest first */
    List<PendingType> pending();

    /** @return what the BMS did (installs, failures, types not found, events given up on), oldest first; bounded */
    List<HistoryEntry> history();

    /** @return the counters since the BMS started */
    ManagerCounters counters();
}
