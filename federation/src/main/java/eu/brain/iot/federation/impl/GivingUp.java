package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.ArrayDeque;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

import eu.brain.iot.federation.impl.Journal.Pending;
import eu.brain.iot.federation.impl.RemoteNode.Presence;

/**
 * The recovery step for the events kept for a node that stays offline: once it has been offline for
 * {@link Settings#offlineGiveUpMillis} (its status unchanged since), its outbox gives them up ({@link Outbox#abandon}:
 * sent and not acknowledged, or not sent yet; a new sequence for that node) and they are published again on this
 * node's bus, oldest first, to the consumers registered after each was first published, which cannot have had it (a
 * behaviour installed since, here or on another node), or, when nothing consumes one at all, to the BMS, which holds
 * it for the behaviour it installs ({@code RemoteEvents.tryDeliverGivenUp}): a node killed for good does not keep
 * them for ever, nor a behaviour that waits for an answer to one of them (a robot's offer to an orchestrator that ran
 * there) wait for ever. Events this node read from its journal at start (published by its earlier run) go to the BMS
 * only when nothing consumes them at all: every consumer is registered since, and some had them then. The node, if
 * it comes back away that long, joins with a clean broker session ({@link LastConnected}), so that the copies its old
 * session queued do not reach it too. An event it took just before it went (its acknowledgement lost) may be taken
 * again by the consumer that came since.
 * <p>
 * Threads: the fabric's inbound thread only.
 */
final class GivingUp {

    /** Back-off before offering again an event the bus refused (a full queue). */
    static final long BUS_RETRY_MILLIS = 5;

    private final Settings settings;
    private final Host host;
    private final Wire wire;
    private final ScheduledExecutorService in;
    private final Function<String, RemoteNode> nodes;
    private final Map<String, Outbox> outboxes;
    /** Events given up and not yet accepted by the bus, oldest first. */
    private final ArrayDeque<GivenUp> again = new ArrayDeque<>();
    private boolean retryScheduled;

    GivingUp(Settings settings, Host host, Wire wire, ScheduledExecutorService in, Function<String, RemoteNode> nodes,
            Map<String, Outbox> outboxes) {
        this.settings = settings;
        this.host = host;
        this.wire = wire;
        this.in = in;
        this.nodes = nodes;
        this.outboxes = outboxes;
    }

    /** A node was seen going offline, its status naming the connection {@code since}: look again later. */
    void wentOffline(String node, long since) {
        long seenMillis = System.currentTimeMillis();
        in.schedule(() -> giveUpIfStillAway(node, since, seenMillis), settings.offlineGiveUpMillis(),
                TimeUnit.MILLISECONDS);
    }

    private void giveUpIfStillAway(String name, long since, long seenMillis) {
        RemoteNode node = nodes.apply(name);
        Outbox outbox = outboxes.get(name);
        if (node.status != Presence.OFFLINE || node.statusSince != since || outbox == null || outbox.backlog() == 0) {
            return;
        }
        Outbox.Abandoned abandoned;
        try {
            abandoned = outbox.abandon();
        } catch (IOException e) {
            host.warn("Fabric {}: the events kept for node {} (offline) could not be given up, its journal not "
                    + "written ({}); tried again in {} ms", settings.fabric(), name, e.getMessage(),
                    settings.offlineGiveUpMillis());
            in.schedule(() -> giveUpIfStillAway(name, since, seenMillis), settings.offlineGiveUpMillis(),
                    TimeUnit.MILLISECONDS);
            return;
        }
        List<Pending> taken = abandoned.events();
        int unreadable = 0;
        for (Pending p : taken) {
            try {
                Wire.Event e = wire.readEvent(p.json());
                // an earlier run's event: every consumer now registered since, none counts as new (see class comment)
                long published = p.seq() <= abandoned.restoredThrough() ? Long.MAX_VALUE
                        : publishedMillis(e.data(), seenMillis);
                again.addLast(new GivenUp(e, published));
            } catch (Wire.MalformedException e) {
                unreadable++;
            }
        }
        host.warn("Fabric {}: node {} stayed offline for {} ms: the {} event(s) kept for it are published again "
                + "here, for the consumers registered since{}; it starts a new sequence from this node when back",
                settings.fabric(), name, settings.offlineGiveUpMillis(), taken.size() - unreadable,
                unreadable == 0 ? "" : " (" + unreadable + " unreadable in the journal, dropped)");
        publishSome();
    }

    /** An event given up, with when it was first published. */
    private record GivenUp(Wire.Event event, long publishedMillis) {
    }

    /**
     * When an event was first published: its {@code timestamp} (the bus sets it at publication; ISO-8601 text on the
     * wire), else when its destination was seen offline (it was published before that).
     */
    static long publishedMillis(Map<String, Object> data, long seenOfflineMillis) {
        Object t = data.get("timestamp");
        if (t instanceof String text) {
            try {
                return Math.min(Instant.parse(text).toEpochMilli(), seenOfflineMillis);
            } catch (DateTimeParseException e) {
                return seenOfflineMillis;
            }
        }
        return seenOfflineMillis;
    }

    /** Offer the events given up to the bus in order; when it refuses one, the rest wait and are offered again. */
    private void publishSome() {
        retryScheduled = false;
        while (!again.isEmpty()) {
            GivenUp g = again.peekFirst();
            Wire.Event e = g.event();
            if (!host.remoteEvents().tryDeliverGivenUp(e.type(), e.types(), e.data(), g.publishedMillis())) {
                if (!retryScheduled) {
                    retryScheduled = true;
                    in.schedule(this::publishSome, BUS_RETRY_MILLIS, TimeUnit.MILLISECONDS);
                }
                return;
            }
            again.pollFirst();
        }
    }
}
