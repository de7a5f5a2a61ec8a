package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;

import eu.brain.iot.federation.impl.Journal.Pending;

/**
 * The events this node publishes to one other node, numbered in one sequence (its epoch and a counter from 1), kept
 * (in memory and in a {@link Journal}) until that node acknowledges them.
 * <p>
 * Events move from {@link #unsent} to {@link #unacked} when the sender takes them for a message, and back to the
 * front of {@link #unsent} when they must be sent again (a reconnection, or no acknowledgement within the resend
 * timeout). An acknowledgement covers every event up to a sequence number. An event is in the journal, handed to the
 * operating system, before it is taken for a message ({@link #writeJournal}, {@link #journaledThrough}).
 * <p>
 * Threads: publishers and the bus's delivery workers append (forwarders of this destination; several may run at
 * once; a publisher only while there is room, {@link #tryAppend}), the sender
 * thread writes the journal and takes batches, the inbound thread applies acknowledgements; the queues are under this
 * object's monitor, which no file write holds (a write that stalls in the operating system would stall every
 * publisher to this node), and the journal under {@link #journalLock}, held by the sender thread and by
 * {@link #close}. An appender waits while {@code maxPending} events are kept (the bus then pushes back on
 * publishers, as for a full queue).
 */
final class Outbox implements AutoCloseable {

    private final String destination;
    private final Journal journal;
    /** Changed only by {@link #abandon}, under both {@link #journalLock} and this object's monitor. */
    private volatile String epoch;
    /** The highest sequence number read from the journal at start: events up to it were published before. */
    private long restoredThrough;
    private final int maxPending;
    private final NodeStats stats;

    private long lastSeq;
    private long ackedThrough;
    private final ArrayDeque<Pending> unacked = new ArrayDeque<>();
    private final ArrayDeque<Pending> unsent = new ArrayDeque<>();
    /** Events appended and not yet in the journal, in sequence order. */
    private final ArrayDeque<Pending> unjournaled = new ArrayDeque<>();
    /** The highest sequence number the journal holds (all lower ones are in it or acknowledged). */
    private long journaledThrough;
    /** The highest sequence number of this epoch this run put on the wire: a lower one sent is sent again. */
    private long sentThrough;
    /** An acknowledgement the journal does not record yet; 0: none. */
    private long ackToRecord;
    private final Object journalLock = new Object();
    /** When the last acknowledgement that freed events came, or the oldest unacknowledged event was sent. */
    private long progressNanos = System.nanoTime();
    private boolean closed;

    Outbox(String destination, Path file, int maxPending, NodeStats stats) throws IOException {
        this.destination = destination;
        this.maxPending = maxPending;
        this.stats = stats;
        List<Journal.Loaded> loaded = new ArrayList<>(1);
        this.journal = Journal.open(file, loaded);
        Journal.Loaded l = loaded.get(0);
        this.epoch = l.epoch();
        this.lastSeq = l.lastSeq();
        this.ackedThrough = l.ackedThrough();
        this.journaledThrough = l.lastSeq();
        this.restoredThrough = l.lastSeq();
        this.unsent.addAll(l.pending());
        stats.backlog(unsent.size());
    }

    String destination() {
        return destination;
    }

    String epoch() {
        return epoch;
    }

    /**
     * Keep one event for the destination, waiting while the outbox is full.
     *
     * @param encoder makes the event's JSON for its sequence number
     * @throws InterruptedException when the waiting appender is interrupted (its forwarder is going away)
     */
    synchronized void append(java.util.function.LongFunction<byte[]> encoder) throws InterruptedException {
        while (!closed && full()) {
            wait();
        }
        if (closed) {
            throw new IllegalStateException("the fabric connection to " + destination + " is closed");
        }
        keep(encoder);
    }

    /**
     * Keep one event for the destination if there is room now, never waiting (a publisher's own thread).
     *
     * @param encoder makes the event's JSON for its sequence number
     * @return whether it was kept; {@code false} when the outbox is full or closed (nothing kept)
     */
    synchronized boolean tryAppend(java.util.function.LongFunction<byte[]> encoder) {
        if (closed || full()) {
            return false;
        }
        keep(encoder);
        return true;
    }

    private boolean full() {
        return unsent.size() + unacked.size() >= maxPending;
    }

    private void keep(java.util.function.LongFunction<byte[]> encoder) {
        long seq = lastSeq + 1;
        Pending p = new Pending(seq, encoder.apply(seq));
        lastSeq = seq;
        unsent.addLast(p);
        unjournaled.addLast(p);
        stats.backlog(unsent.size() + unacked.size());
    }

    /**
     * Hand the events appended since the last call, and the last acknowledgement, to the journal and the operating
     * system; compact the journal when it has grown. Called by the sender thread, whether or not the destination is
     * online: a publishing node killed keeps what it accepted for a node that is away. When the write fails, the
     * events stay unsent and are written at the next call.
     */
    void writeJournal() throws IOException {
        synchronized (journalLock) {
            List<Pending> events;
            long ack;
            List<Pending> keep = null;
            long through;
            synchronized (this) {
                if (closed || unjournaled.isEmpty() && ackToRecord == 0) {
                    return;
                }
                events = new ArrayList<>(unjournaled);
                unjournaled.clear();
                ack = ackToRecord;
                ackToRecord = 0;
                through = events.isEmpty() ? journaledThrough : events.get(events.size() - 1).seq();
                if (journal.wantsCompaction() && unacked.size() + unsent.size() < 10_000) {
                    keep = new ArrayList<>(unacked);
                    keep.addAll(unsent);
                    through = lastSeq;
                }
            }
            try {
                if (keep != null) {
                    journal.rewrite(epoch, through, keep); // every event up to 'through' is acknowledged or kept
                } else {
                    for (Pending p : events) {
                        journal.append(p.seq(), p.json());
                    }
                    if (ack > 0) {
                        journal.acked(ack);
                    }
                    journal.flush();
                }
            } catch (IOException e) {
                synchronized (this) { // written again at the next call; not sent before
                    for (int i = events.size() - 1; i >= 0; i--) {
                        unjournaled.addFirst(events.get(i));
                    }
                    ackToRecord = Math.max(ackToRecord, ack);
                }
                throw e;
            }
            synchronized (this) {
                journaledThrough = Math.max(journaledThrough, through);
            }
        }
    }

    /** @return whether events wait to be sent */
    synchronized boolean hasUnsent() {
        return !unsent.isEmpty();
    }

    /** Events taken for one message, with the epoch they are numbered in. */
    record Taken(String epoch, List<Pending> events) {
    }

    /** Take up to {@code max} events to send, with their epoch (read in the same step: see {@link #abandon}). */
    synchronized Taken takeBatch(int max) {
        return new Taken(epoch, take(max));
    }

    /** Take up to {@code max} events to send, among those the journal holds ({@link #writeJournal} first). */
    synchronized List<Pending> take(int max) {
        List<Pending> batch = new ArrayList<>(Math.min(max, unsent.size()));
        while (batch.size() < max && !unsent.isEmpty() && unsent.peekFirst().seq() <= journaledThrough) {
            Pending p = unsent.pollFirst();
            batch.add(p);
            unacked.addLast(p);
        }
        if (!batch.isEmpty() && unacked.size() == batch.size()) {
            progressNanos = System.nanoTime();
        }
        return batch;
    }

    /**
     * Events taken for a message are on the wire (the broker took the publication): counted as sent, and those of
     * them sent before as sent again. Counted here, not when taken nor when rewound: a publication that fails leaves
     * its events to be sent after the reconnection (their first sending), and an event rewound that is
     * acknowledged before it goes again is not sent again.
     */
    synchronized void sent(Taken taken) {
        List<Pending> events = taken.events();
        int again = 0;
        if (taken.epoch().equals(epoch)) { // else given up meanwhile: a new sequence starts at 1
            for (Pending p : events) {
                if (p.seq() <= sentThrough) {
                    again++;
                }
            }
            sentThrough = Math.max(sentThrough, events.isEmpty() ? 0 : events.get(events.size() - 1).seq());
        }
        stats.sent.add(events.size());
        stats.resent(again);
    }

    /** The destination took every event up to {@code through}; the journal records it at its next write. */
    synchronized void acked(String ackEpoch, long through) {
        if (!epoch.equals(ackEpoch) || through <= ackedThrough) {
            return;
        }
        ackedThrough = Math.min(through, lastSeq);
        int freed = drop(unacked, ackedThrough) + drop(unsent, ackedThrough);
        if (freed > 0) {
            progressNanos = System.nanoTime();
            stats.acked(freed);
            notifyAll();
        }
        ackToRecord = ackedThrough;
        stats.backlog(unsent.size() + unacked.size());
    }

    private static int drop(ArrayDeque<Pending> queue, long through) {
        int n = 0;
        while (!queue.isEmpty() && queue.peekFirst().seq() <= through) {
            queue.pollFirst();
            n++;
        }
        return n;
    }

    /**
     * Send again what was sent but not acknowledged: at once ({@code force}, after a reconnection), or when nothing
     * was acknowledged for {@code timeoutMillis}.
     *
     * @return how many events are to be sent again
     */
    synchronized int rewind(boolean force, long timeoutMillis) {
        if (unacked.isEmpty()
                || !force && System.nanoTime() - progressNanos < TimeUnit.MILLISECONDS.toNanos(timeoutMillis)) {
            return 0;
        }
        int n = unacked.size();
        while (!unacked.isEmpty()) {
            unsent.addFirst(unacked.pollLast());
        }
        progressNanos = System.nanoTime();
        return n; // counted as sent again when they go again (sent)
    }

    /**
     * Give up on the destination (it stayed offline too long, {@link GivingUp}): every event kept for it, sent and not
     * acknowledged or not sent yet, is taken out in sequence order, and the outbox starts a new sequence (a new epoch,
     * numbered from 1) in memory and in the journal. An acknowledgement of the old epoch is ignored from then on.
     *
     * @return the events taken out, oldest first, and which of them were read from the journal at start
     * @throws IOException when the journal could not be written: nothing was taken out
     */
    Abandoned abandon() throws IOException {
        synchronized (journalLock) {
            String newEpoch = UUID.randomUUID().toString();
            journal.rewrite(newEpoch, 0, List.of());
            List<Pending> taken;
            long restored;
            synchronized (this) {
                restored = restoredThrough;
                restoredThrough = 0;
                taken = new ArrayList<>(unacked);
                taken.addAll(unsent);
                unacked.clear();
                unsent.clear();
                unjournaled.clear();
                epoch = newEpoch;
                lastSeq = 0;
                ackedThrough = 0;
                sentThrough = 0;
                journaledThrough = 0;
                ackToRecord = 0;
                progressNanos = System.nanoTime();
                stats.backlog(0);
                notifyAll(); // appenders waiting for room
            }
            return new Abandoned(taken, restored);
        }
    }

    /**
     * Events given up: those numbered up to {@code restoredThrough} were read from the journal at start (published by
     * an earlier run of this node, whose consumers this run cannot tell apart from new ones).
     */
    record Abandoned(List<Pending> events, long restoredThrough) {
    }

    synchronized int backlog() {
        return unsent.size() + unacked.size();
    }

    @Override
    public void close() throws IOException {
        synchronized (this) {
            closed = true;
            notifyAll();
        }
        synchronized (journalLock) {
            journal.close();
        }
    }
}
