package eu.brain.iot.edge.model.api;

import org.osgi.annotation.versioning.ProviderType;

/** The edge's polling and publishing counters, registered by the edge beside its {@link DeviceModel}. Since 1.1. */
@ProviderType
public interface PollMonitor {

    /** @return a fresh snapshot of the counters */
    PollStatistics statistics();
}
