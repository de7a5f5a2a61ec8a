package eu.brain.iot.federation.impl;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Another node of the fabric as this node knows it: its presence, its interest, and the forwarders registered with
 * the local bus for it (one per interest entry, while it is online).
 * <p>
 * Threads: owned by the fabric's inbound thread (Paho's callback thread may make one, through the node table, for a
 * batch of events it takes, and counts in its {@link #stats}); the commands read {@link #status} and
 * {@link #interest}, which are volatile and replaced, never changed.
 */
final class RemoteNode {

    enum Presence { UNKNOWN, ONLINE, OFFLINE }

    final String name;
    final NodeStats stats = new NodeStats();
    volatile Presence status = Presence.UNKNOWN;
    volatile List<InterestEntry> interest = List.of();
    volatile long interestSent;
    /** The connection the applied status is about ({@link Wire.Status#since}). */
    long statusSince;
    final Map<InterestEntry, AutoCloseable> forwarders = new LinkedHashMap<>();

    RemoteNode(String name) {
        this.name = name;
    }
}
