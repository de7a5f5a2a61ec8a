package eu.brain.iot.eventing.monitoring.api;

import java.util.List;

import org.osgi.annotation.versioning.ProviderType;

/**
 * Live counters of the event bus, registered as a service by the bus. Each call returns a fresh snapshot.
 */
@ProviderType
public interface EventBusStatistics {

    /** @return per event type: published, delivered, failed and unhandled counts, sorted by type name */
    List<EventTypeStatistics> eventTypes();

    /** @return per registered consumer: its queue depth, deliveries and failures, sorted by consumer name */
    List<ConsumerStatistics> consumers();
}
