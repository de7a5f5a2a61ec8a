package eu.brain.iot.federation.impl;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.function.LongSupplier;

import eu.brain.iot.federation.impl.FabricNode.NodeView;
import eu.brain.iot.federation.monitoring.api.FabricStatus;
import eu.brain.iot.federation.monitoring.api.RemoteNodeStatus;

/**
 * The fabric as {@link eu.brain.iot.federation.monitoring.api.FabricMonitor} shows it: the fabric node's views
 * ({@link FabricNode#nodes()}) mapped to the monitoring API's DTOs, with when each node was first seen in its status.
 * A status change is noted when it is read, so its time is exact to the readers' period.
 * <p>
 * Threads: any caller (the dashboard's thread, Gogo's); {@link #read} is synchronized on this object, which guards
 * {@link #seen}. The views it maps are snapshots taken from volatile fields and counters, safe on any thread.
 */
final class Monitor {

    /** A node's status as last read, and when it was first read so. */
    private record Seen(String status, long since) {
    }

    private final LongSupplier clock;
    /** By node name (this node's included); names no longer listed are forgotten. */
    private final Map<String, Seen> seen = new HashMap<>();

    /** @param clock milliseconds since the epoch */
    Monitor(LongSupplier clock) {
        this.clock = clock;
    }

    /**
     * @param self this node's name
     * @param state {@link FabricStatus#ONLINE}, {@link FabricStatus#JOINING} or {@link FabricStatus#NOT_JOINED}
     * @param problem why the node does not join, or {@code null}
     * @param views the fabric node's views, this node's own among them (it gives this node's interest); empty for a
     *        node that does not join
     * @param installed the behaviours this node's installer installed, {@code null} without an installer
     */
    synchronized FabricStatus read(String self, String fabric, String brokerUri, String state, String problem,
            List<NodeView> views, Integer installed) {
        long now = clock.getAsLong();
        Map<String, Seen> still = new HashMap<>();
        FabricStatus out = new FabricStatus();
        out.node = self;
        out.fabric = fabric;
        out.brokerUri = brokerUri;
        out.state = state;
        out.since = seen(still, self, state, now);
        out.problem = problem;
        out.interestEntries = 0;
        out.eventTypes = List.of();
        out.installedBehaviours = installed;
        out.remotes = new ArrayList<>();
        for (NodeView v : views) {
            if (v.node().equals(self)) {
                out.interestEntries = v.interest().size();
                out.eventTypes = eventTypes(v.interest());
            } else {
                RemoteNodeStatus r = remote(v);
                r.since = seen(still, r.name, r.status, now);
                out.remotes.add(r);
            }
        }
        out.remotes.sort((a, b) -> a.name.compareTo(b.name));
        seen.clear();
        seen.putAll(still);
        return out;
    }

    private long seen(Map<String, Seen> still, String name, String status, long now) {
        Seen before = seen.get(name);
        Seen s = before != null && before.status().equals(status) ? before : new Seen(status, now);
        still.put(name, s);
        return s.since();
    }

    /** One remote node's view as the API's DTO, without {@link RemoteNodeStatus#since} (the caller's to note). */
    static RemoteNodeStatus remote(NodeView v) {
        RemoteNodeStatus r = new RemoteNodeStatus();
        r.name = v.node();
        r.status = switch (v.status()) {
        case RemoteNodeStatus.ONLINE -> RemoteNodeStatus.ONLINE;
        case RemoteNodeStatus.OFFLINE -> RemoteNodeStatus.OFFLINE;
        default -> RemoteNodeStatus.UNKNOWN;
        };
        r.interestEntries = v.interest().size();
        r.eventTypes = eventTypes(v.interest());
        NodeStats.Snapshot s = v.stats();
        r.sent = s.sent();
        r.resent = s.resent();
        r.acknowledged = s.acked();
        r.backlog = s.backlog();
        r.received = s.received();
        r.duplicates = s.duplicates();
        r.refused = s.refused();
        r.installedBehaviours = null; // a node's load travels only inside install bids: not kept here
        return r;
    }

    /** The event types of some interest entries: each once, sorted. */
    static List<String> eventTypes(Collection<InterestEntry> entries) {
        TreeSet<String> types = new TreeSet<>();
        entries.forEach(e -> types.addAll(e.types()));
        return List.copyOf(types);
    }
}
