package eu.brain.iot.federation.impl;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;

/**
 * What passed between this node and one other node. Counters are written by whichever thread sees the fact (the
 * bus's delivery workers, the sender, the inbound thread) and read by the commands: adders and atomics only.
 */
public final class NodeStats {

    final LongAdder sent = new LongAdder();
    final LongAdder resent = new LongAdder();
    final LongAdder acked = new LongAdder();
    final LongAdder received = new LongAdder();
    final LongAdder duplicates = new LongAdder();
    final LongAdder unsigned = new LongAdder();
    final LongAdder badSignature = new LongAdder();
    final LongAdder replayed = new LongAdder();
    final LongAdder malformed = new LongAdder();
    final LongAdder redelivered = new LongAdder();
    private final AtomicLong backlog = new AtomicLong();

    void backlog(long events) {
        backlog.set(events);
    }

    void acked(int events) {
        acked.add(events);
    }

    void resent(int events) {
        resent.add(events);
    }

    /** A snapshot for the commands and the tests. */
    public record Snapshot(long sent, long resent, long acked, long received, long duplicates, long refused,
            long unsigned, long badSignature, long replayed, long malformed, long backlog) {
    }

    public Snapshot snapshot() {
        long u = unsigned.sum();
        long b = badSignature.sum();
        long r = replayed.sum();
        long m = malformed.sum();
        return new Snapshot(sent.sum(), resent.sum(), acked.sum(), received.sum(), duplicates.sum(), u + b + r + m, u,
                b, r, m, backlog.get());
    }
}
