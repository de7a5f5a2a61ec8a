package eu.brain.iot.federation.monitoring.api;

import org.osgi.annotation.versioning.ProviderType;

/**
 * This node's view of its fabric, registered as a service by the federation bundle while the node has a fabric
 * configuration (PID {@code eu.brain.iot.federation}); a node without one has no such service. Each call returns a
 * fresh snapshot, answered from memory (no network); callable from any thread.
 */
@ProviderType
public interface FabricMonitor {

    /** @return this node, its connection, and one entry per other node it knows, sorted by name */
    FabricStatus status();

    /**
     * Messages refused (unsigned, wrongly signed, replayed, malformed, or removing a retained message) that claimed
     * to come from names no verified message came from, or that were published on this node's own retained topics,
     * since this node started: what a client of the broker without the fabric's key tried, which no
     * {@link RemoteNodeStatus} counts so that it adds no node. The same total as {@code fabric:stats}' row
     * {@code (unverified)}.
     *
     * @return that total; 0 when this node does not join, and from a provider that does not count them
     * @since 1.1
     */
    default long unverifiedRefused() {
        return 0;
    }
}
