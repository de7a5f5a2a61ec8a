package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.BooleanSupplier;

import eu.brain.iot.eventing.spi.RemoteEvents;
import eu.brain.iot.federation.impl.Wire.Event;

/**
 * The events one other node publishes to this node: each into the local behaviours exactly once and in its sequence
 * order. An event whose sequence number was taken already is dropped as a duplicate; one that comes early (an earlier
 * one was lost on the way and will be sent again) waits in {@link #early}, bounded; the next expected one is offered to
 * the bus ({@link RemoteEvents#tryDeliverRemote}), and when every behaviour that took it returned from {@code notify},
 * it counts as done. While the node is starting, an event no behaviour takes yet waits in {@link #parked} with every
 * later event of its type, and the events of other types go on past it: an event kept for a behaviour that is still
 * coming up, or that this node no longer runs, does not hold up its publisher's other events (its leases, its beats).
 * Parked events are offered again first, in order; once the node has started they go to the bus's unhandled rules
 * before any later event. The window, the highest sequence number up to which every event is done ({@code epoch
 * through}), is written to a file the moment it moves (one positioned write in place, handed to the operating system:
 * it survives the node's process being killed), and acknowledged soon after: after a restart of this node, events up to
 * it are duplicates, and events after it are delivered again: those that were waiting in the bus, which no behaviour
 * had seen, and one caught inside {@code notify} by the crash.
 * <p>
 * Threads: whoever holds the {@link Inboxes}' monitor (Paho's callback thread taking a batch, the fabric's inbound
 * thread offering again or acknowledging) owns everything but {@link #done} and {@link #doneAhead}, which the
 * completions update (via {@link #completed}) under this object's monitor: the bus runs them on its delivery workers,
 * or at once on the thread that offered an event no behaviour takes.
 */
final class Inbox {

    /**
     * How long after its start a node keeps an event that none of its behaviours takes yet, offering it again, before
     * the bus's unhandled rules apply: its behaviours may still be coming up (restored from the installer's journal,
     * installed from the configuration folder) when events sent to it before it stopped arrive.
     */
    static final long STARTING_NANOS = java.util.concurrent.TimeUnit.SECONDS.toNanos(10);
    /** Events kept that came before an earlier one; beyond this they are dropped (and sent again later). */
    static final int MAX_EARLY = 50_000;

    private final String publisher;
    /** Fixed length of the window record, written in place. */
    static final int WINDOW_BYTES = 96;

    private final FileChannel window;
    private final NodeStats stats;
    private final BooleanSupplier starting;

    /** The publisher's sequence stream (written under the {@link Inboxes}' monitor and this one). */
    private String epoch;
    /** The next sequence number to offer to the bus. */
    private long next;
    private final TreeMap<Long, Event> early = new TreeMap<>();
    /** Events taken out of order while starting: none of this node's behaviours took them yet. */
    private final TreeMap<Long, Event> parked = new TreeMap<>();
    /** Every event up to this one is done (guarded by this). */
    private long done;
    private final TreeSet<Long> doneAhead = new TreeSet<>();
    /** The window written and acknowledged last. */
    private long ackedThrough = -1;
    private boolean ackAgain;
    /** Set when the node stops (guarded by this). */
    private boolean closed;

    /**
     * @param starting while true, an event no local behaviour takes yet waits (this node's behaviours are still
     *                 coming up, and events sent before it stopped may reach it first); then the bus's unhandled
     *                 rules apply
     */
    Inbox(String publisher, Path windowFile, NodeStats stats, BooleanSupplier starting) throws IOException {
        this.publisher = publisher;
        this.stats = stats;
        this.starting = starting;
        Files.createDirectories(windowFile.toAbsolutePath().getParent());
        if (Files.exists(windowFile)) {
            String[] parts = Files.readString(windowFile, StandardCharsets.US_ASCII).trim().split(" ");
            if (parts.length == 2 && parts[1].matches("[0-9]{1,19}")) {
                epoch = parts[0];
                done = Long.parseLong(parts[1]);
                next = done + 1;
                ackedThrough = done;
            }
        }
        this.window = FileChannel.open(windowFile, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
    }

    String publisher() {
        return publisher;
    }

    /**
     * Take a batch's events, then offer what is next in order to the bus.
     *
     * @return whether events wait because the bus refused one, or none of this node's behaviours takes it yet while
     *         it is starting (the caller offers again later)
     */
    boolean accept(String batchEpoch, List<Event> events, RemoteEvents bus, Runnable onDone) {
        if (!batchEpoch.equals(epoch)) {
            restart(batchEpoch);
        }
        for (Event e : events) {
            if (e.seq() < next || early.containsKey(e.seq())) {
                stats.duplicates.increment();
                ackAgain = true; // the publisher did not get an acknowledgement: send it again
            } else if (early.size() < MAX_EARLY || e.seq() == next) {
                early.put(e.seq(), e);
            }
        }
        return offer(bus, onDone);
    }

    /** A new sequence stream from this publisher (its state was reset): its numbers start again. */
    private void restart(String newEpoch) {
        early.clear();
        parked.clear();
        next = 1;
        synchronized (this) {
            epoch = newEpoch;
            done = 0;
            doneAhead.clear();
            writeWindow();
        }
        ackedThrough = -1;
    }

    /** @return whether events wait because the bus refused one, or none of this node's behaviours takes it yet */
    boolean offer(RemoteEvents bus, Runnable onDone) {
        boolean startingNow = starting.getAsBoolean();
        Set<String> held = new HashSet<>(); // types with an event waiting: their later events wait behind it
        for (var it = parked.values().iterator(); it.hasNext();) {
            Event e = it.next();
            if (held.contains(e.type()) || !deliver(bus, e, startingNow, onDone)) {
                if (!startingNow) {
                    return true; // started: in order again, from the first one parked
                }
                held.add(e.type());
                continue;
            }
            it.remove();
        }
        while (!early.isEmpty() && early.firstKey() == next) {
            Event e = early.firstEntry().getValue();
            if (held.contains(e.type()) || !deliver(bus, e, startingNow, onDone)) {
                if (!startingNow || parked.size() + early.size() > MAX_EARLY) {
                    return true;
                }
                held.add(e.type());
                parked.put(e.seq(), e);
            }
            early.pollFirstEntry();
            next++;
        }
        return !parked.isEmpty();
    }

    /** Offers one event to the bus: while starting, to this node's behaviours only. */
    private boolean deliver(RemoteEvents bus, Event e, boolean startingNow, Runnable onDone) {
        long seq = e.seq();
        String forEpoch = epoch;
        Map<String, Object> data = e.data();
        data.putIfAbsent("sourceNode", publisher);
        Runnable done = () -> completed(forEpoch, seq, onDone);
        boolean taken = startingNow ? bus.tryDeliverRemoteToBehaviours(e.type(), e.types(), data, done)
                : bus.tryDeliverRemote(e.type(), e.types(), data, done);
        if (taken) {
            stats.received.increment();
        }
        return taken;
    }

    private void completed(String forEpoch, long seq, Runnable onDone) {
        boolean advanced = false;
        synchronized (this) {
            if (closed || !forEpoch.equals(epoch)) {
                return; // the node is stopping: what is not written yet is delivered again after its restart
            }
            if (seq == done + 1) {
                done = seq;
                while (!doneAhead.isEmpty() && doneAhead.first() == done + 1) {
                    done = doneAhead.pollFirst();
                }
                writeWindow();
                advanced = true;
            } else if (seq > done) {
                doneAhead.add(seq);
            }
        }
        if (advanced) {
            onDone.run();
        }
    }

    /** Write the window in place (under the monitor). */
    private void writeWindow() {
        String record = epoch + " " + done;
        byte[] bytes = (record + " ".repeat(Math.max(0, WINDOW_BYTES - 1 - record.length())) + "\n")
                .getBytes(StandardCharsets.US_ASCII);
        try {
            window.write(ByteBuffer.wrap(bytes), 0);
        } catch (IOException e) {
            throw new UncheckedIOException("the fabric window of " + publisher + " cannot be written", e);
        }
    }

    /** What to acknowledge now, if anything. */
    Wire.Ack ackToSend(String self, long now) {
        long through;
        String e;
        synchronized (this) {
            through = done;
            e = epoch;
        }
        if (e == null || through == ackedThrough && !ackAgain) {
            return null;
        }
        ackedThrough = through;
        ackAgain = false;
        return new Wire.Ack(self, publisher, e, through, now);
    }

    void close() throws IOException {
        synchronized (this) {
            closed = true;
            window.close();
        }
    }
}
