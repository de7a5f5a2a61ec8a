package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The events other nodes publish to this node: one {@link Inbox} per publisher, the events the bus refused (a full
 * local queue) offered again, and the acknowledgements of the events done.
 * <p>
 * Threads: Paho's callback thread hands in the batches ({@link #accept}), the fabric's inbound thread offers again
 * what the bus refused and sends the acknowledgements; the inboxes are theirs under this object's monitor, which
 * neither holds while publishing. The events' completions call {@link #eventsDone} when events are done, on the
 * bus's delivery workers or at once on the thread that offered an event no behaviour takes (it only schedules the
 * acknowledgements on the inbound thread).
 */
final class Inboxes {

    /** Back-off before offering again events the bus refused (a full local queue). */
    static final long BUS_RETRY_MILLIS = 2;
    /**
     * How long the acknowledgements of events done wait to be sent together: each acknowledges every event of its
     * publisher done so far, so one per few milliseconds is enough, where one per event doubled the messages through
     * the broker and, whenever the broker was slow to confirm, held the inbound thread (and the events behind it).
     */
    static final long ACK_DELAY_MILLIS = 5;

    private final Settings settings;
    private final Host host;
    private final Wire wire;
    private final Topics topics;
    private final MqttLink link;
    private final ScheduledExecutorService in;
    /** When this node was made: for {@link Inbox#STARTING_NANOS} after, events wait for the behaviours they are for. */
    private final long madeNanos = System.nanoTime();

    private final Map<String, Inbox> inboxes = new ConcurrentHashMap<>();
    /** Guarded by this. */
    private final Set<Inbox> refused = new LinkedHashSet<>();
    private final AtomicBoolean ackPending = new AtomicBoolean();
    /** Set when the node stops: no batch is taken after (guarded by this). */
    private boolean closed;

    Inboxes(Settings settings, Host host, Wire wire, Topics topics, MqttLink link, ScheduledExecutorService in) {
        this.settings = settings;
        this.host = host;
        this.wire = wire;
        this.topics = topics;
        this.link = link;
        this.in = in;
    }

    /** A batch from {@code from}, checked already: its events into the local behaviours, once each, in order. */
    synchronized void accept(String from, Wire.Batch batch, NodeStats stats) throws IOException {
        if (closed) {
            return; // sent again to this node after its restart: nothing of it was acknowledged
        }
        Inbox inbox = inboxes.get(from);
        if (inbox == null) {
            inbox = new Inbox(from, settings.stateDir().resolve("inbox").resolve(from + ".window"), stats,
                    () -> System.nanoTime() - madeNanos < Inbox.STARTING_NANOS);
            inboxes.put(from, inbox);
        }
        long dupsBefore = stats.duplicates.sum();
        if (inbox.accept(batch.epoch(), batch.events(), host.remoteEvents(), this::eventsDone)) {
            retryLater(inbox);
        }
        if (stats.duplicates.sum() != dupsBefore) {
            eventsDone();
        }
    }

    private void retryLater(Inbox inbox) {
        if (refused.add(inbox) && refused.size() == 1) {
            in.schedule(this::offerRefused, BUS_RETRY_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    private synchronized void offerRefused() {
        if (closed) {
            return;
        }
        List<Inbox> again = new ArrayList<>(refused);
        refused.clear();
        for (Inbox inbox : again) {
            if (inbox.offer(host.remoteEvents(), this::eventsDone)) {
                retryLater(inbox);
            }
        }
    }

    /**
     * Called when events of a publisher are done (see the threads above) or came twice: acknowledged
     * {@link #ACK_DELAY_MILLIS} later, with those done meanwhile, on the inbound thread.
     */
    private void eventsDone() {
        if (ackPending.compareAndSet(false, true)) {
            in.schedule(this::flushAcks, ACK_DELAY_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    /** Acknowledge to each publisher the events done since its last acknowledgement (also after a reconnection). */
    void flushAcks() {
        ackPending.set(false);
        if (!link.isConnected()) {
            return;
        }
        long now = System.currentTimeMillis();
        for (Inbox inbox : inboxes.values()) {
            try {
                if (!link.publishIfRoom(topics.acks(inbox.publisher(), settings.node()), () -> {
                    Wire.Ack ack;
                    synchronized (this) {
                        ack = inbox.ackToSend(settings.node(), now);
                    }
                    return ack == null ? null : wire.ack(ack);
                })) {
                    eventsDone(); // the broker has not confirmed earlier publications: the inbound thread goes on
                    return;
                }
            } catch (IOException e) {
                host.warn("Fabric {}: acknowledgement to {} not sent ({}); sent again later", settings.fabric(),
                        inbox.publisher(), e.getMessage());
            }
        }
    }

    /** Close every window (first, when the node stops: no window moves after this instant). */
    synchronized void close() {
        closed = true;
        for (Inbox i : inboxes.values()) {
            try {
                i.close();
            } catch (IOException e) {
                host.warn("Fabric {}: window of {} not closed: {}", settings.fabric(), i.publisher(), e.getMessage());
            }
        }
    }
}
