package eu.brain.iot.federation.impl;

import java.util.Collection;
import java.util.List;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import java.util.function.Function;
import java.util.function.LongSupplier;

import eu.brain.iot.eventing.spi.EventForwarder;
import eu.brain.iot.federation.impl.RemoteNode.Presence;

/**
 * Which other nodes are online and what their behaviours consume, and the forwarders on the local bus that follow
 * it: one per interest entry of each online node, added before withdrawn ones go, all gone when the node is offline
 * (its Last Will, or its goodbye). Signatures are checked before anything reaches this class.
 * <p>
 * A node's offline status is believed only once this node's own connection has outlived it by
 * {@link #OFFLINE_CONFIRM_MILLIS}: a broker that shuts down publishes the Last Will of every client it still holds
 * (Mosquitto does) just before it drops them all, this node included. Believed at once, such a will would take
 * the forwarders of a node that is not gone, and the events published until the broker is back would find no
 * consumer.
 * When this node's connection drops meanwhile, the status is dropped: after the reconnection the broker's retained
 * status of that node (or its next one) decides.
 * <p>
 * Threads: the fabric's inbound thread only (its scheduled confirmations run on it too).
 */
final class Membership {

    /** How long this node's own connection must outlive an offline status before it is believed. */
    static final long OFFLINE_CONFIRM_MILLIS = 1000;

    private final String fabric;
    private final Host host;
    private final ScheduledExecutorService in;
    /** This node's connection now: when it started, or -1 while there is none. */
    private final LongSupplier connection;
    private final Function<String, RemoteNode> nodes;
    private final Function<String, Outbox> outboxes;
    private final Function<String, EventForwarder> forwarders;
    /** Told of every node that goes offline, with its status's connection ({@link GivingUp#wentOffline}). */
    private final BiConsumer<String, Long> wentOffline;

    Membership(String fabric, Host host, ScheduledExecutorService in, LongSupplier connection,
            Function<String, RemoteNode> nodes, Function<String, Outbox> outboxes,
            Function<String, EventForwarder> forwarders, BiConsumer<String, Long> wentOffline) {
        this.fabric = fabric;
        this.host = host;
        this.in = in;
        this.connection = connection;
        this.nodes = nodes;
        this.outboxes = outboxes;
        this.forwarders = forwarders;
        this.wentOffline = wentOffline;
    }

    private RemoteNode node(String name) {
        return nodes.apply(name);
    }

    private void outbox(String name) {
        outboxes.apply(name);
    }

    void onInterest(String from, Wire.Interest interest, NodeStats stats) {
        if (!interest.node().equals(from)) {
            stats.malformed.increment();
            return;
        }
        RemoteNode node = node(from);
        if (interest.sent() < node.interestSent) {
            return; // an older announcement than the one applied
        }
        node.interestSent = interest.sent();
        node.interest = List.copyOf(interest.entries());
        syncForwarders(node);
    }

    /**
     * A node's status: online at once, offline once this node's connection has outlived it (class comment).
     *
     * @param applied run after the status was applied
     */
    void onStatus(String from, Wire.Status status, NodeStats stats, Runnable applied) {
        if (!status.node().equals(from)) {
            stats.malformed.increment();
            return;
        }
        if (Wire.Status.ONLINE.equals(status.state())) {
            apply(from, status);
            applied.run();
            return;
        }
        long seenOn = connection.getAsLong();
        in.schedule(() -> {
            if (seenOn >= 0 && connection.getAsLong() == seenOn) {
                apply(from, status);
                applied.run();
            }
        }, OFFLINE_CONFIRM_MILLIS, TimeUnit.MILLISECONDS);
    }

    private void apply(String from, Wire.Status status) {
        RemoteNode node = node(from);
        if (status.since() < node.statusSince) {
            return; // about a connection replaced already (a late Last Will)
        }
        node.statusSince = status.since();
        Presence before = node.status;
        node.status = Wire.Status.ONLINE.equals(status.state()) ? Presence.ONLINE : Presence.OFFLINE;
        if (before != node.status) {
            host.info("Fabric {}: node {} is {}", fabric, from, status.state());
        }
        syncForwarders(node);
        if (before != Presence.OFFLINE && node.status == Presence.OFFLINE) {
            wentOffline.accept(from, node.statusSince);
        }
    }

    /** Forwarders for exactly the interest of an online node: new entries first, then the withdrawn ones go. */
    void syncForwarders(RemoteNode node) {
        List<InterestEntry> wanted = node.status == Presence.ONLINE ? node.interest : List.of();
        if (!wanted.isEmpty()) {
            outbox(node.name); // before the bus can route to it
        }
        EventForwarder forwarder = forwarders.apply(node.name);
        for (InterestEntry e : wanted) {
            if (!node.forwarders.containsKey(e)) {
                node.forwarders.put(e, host.addForwarder(node.name, e, forwarder));
            }
        }
        for (var it = node.forwarders.entrySet().iterator(); it.hasNext();) {
            var entry = it.next();
            if (!wanted.contains(entry.getKey())) {
                it.remove();
                try {
                    entry.getValue().close();
                } catch (Exception e) {
                    host.warn("Fabric {}: a forwarder to {} did not close: {}", fabric, node.name,
                            e.getMessage());
                }
            }
        }
    }


    /** This node leaves: no forwarder stays. */
    void leaveAll(Collection<RemoteNode> all) {
        for (RemoteNode n : all) {
            n.status = Presence.OFFLINE;
            syncForwarders(n);
        }
    }
}
