package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import eu.brain.iot.federation.impl.Journal.Pending;

/**
 * The events this node publishes to one other node, numbered in one sequence (its epoch and a counter from 1), kept
 * (in memory and in a {@link Journal}) until that node acknowledges them.
 * <p>
 * Events move from {@link #unsent} to {@link #unacked} when the sender takes them for a message, and back to the
 * front of {@link #unsent} when they must be sent again (a reconnection, or no acknowledgement within the resend
 * timeout). An acknowledgement covers every event up to a sequence number.
 * <p>
 * Threads: the bus's delivery workers append (forwarders of this destination; several may run at once), the sender
 * thread takes batches, the inbound thread applies acknowledgements; all under this object's monitor. An appender
 * waits while {@code maxPending} events are kept (the bus then pushes back on publishers, as for a full queue).
 */
final class Outbox implements AutoCloseable {

    private final String destination;
    private final Journal journal;
    private final String epoch;
    private final int maxPending;
    private final NodeStats stats;

    private long lastSeq;
    private long ackedThrough;
    private final ArrayDeque<Pending> unacked = new ArrayDeque<>();
    private final ArrayDeque<Pending> unsent = new ArrayDeque<>();
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
        while (!closed && unsent.size() + unacked.size() >= maxPending) {
            wait();
        }
        if (closed) {
            throw new IllegalStateException("the fabric connection to " + destination + " is closed");
        }
        long seq = lastSeq + 1;
        byte[] json = encoder.apply(seq);
        try {
            journal.append(seq, json);
        } catch (IOException e) {
            throw new UncheckedIOException("the fabric journal for " + destination + " cannot be written", e);
        }
        lastSeq = seq;
        unsent.addLast(new Pending(seq, json));
        stats.backlog(unsent.size() + unacked.size());
    }

    /** @return whether events wait to be sent */
    synchronized boolean hasUnsent() {
        return !unsent.isEmpty();
    }

    /**
     * Take up to {@code max} events to send, after handing the journal to the operating system (an event is in the
     * journal before it is on the wire).
     */
    synchronized List<Pending> take(int max) throws IOException {
        journal.flush();
        List<Pending> batch = new ArrayList<>(Math.min(max, unsent.size()));
        while (batch.size() < max && !unsent.isEmpty()) {
            Pending p = unsent.pollFirst();
            batch.add(p);
            unacked.addLast(p);
        }
        if (!batch.isEmpty() && unacked.size() == batch.size()) {
            progressNanos = System.nanoTime();
        }
        return batch;
    }

    /** The destination took every event up to {@code through}. */
    synchronized void acked(String ackEpoch, long through) throws IOException {
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
        journal.acked(ackedThrough);
        if (journal.wantsCompaction() && unacked.size() + unsent.size() < 10_000) {
            List<Pending> keep = new ArrayList<>(unacked);
            keep.addAll(unsent);
            journal.rewrite(epoch, lastSeq, keep);
        }
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
        stats.resent(n);
        return n;
    }

    synchronized int backlog() {
        return unsent.size() + unacked.size();
    }

    @Override
    public synchronized void close() throws IOException {
        closed = true;
        notifyAll();
        journal.close();
    }
}
