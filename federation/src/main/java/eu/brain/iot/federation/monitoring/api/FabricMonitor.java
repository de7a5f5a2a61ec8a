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
}
