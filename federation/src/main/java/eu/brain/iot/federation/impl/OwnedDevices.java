package eu.brain.iot.federation.impl;

/**
 * Which devices of the fleet this node owns (its edge polls and commands them), as its install offers tell the
 * asking node ({@link InstallDesk}). Answered from memory; on a node with an edge, the edge's
 * {@code DeviceOwnership} ({@link EdgeOwnedDevices}), else {@link #NONE}. Implementations are thread-safe.
 */
@FunctionalInterface
interface OwnedDevices {

    /** A node without an edge owns no device. */
    OwnedDevices NONE = id -> false;

    boolean owns(String deviceId);
}
