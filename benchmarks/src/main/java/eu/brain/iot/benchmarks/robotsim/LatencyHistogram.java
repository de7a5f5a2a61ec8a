package eu.brain.iot.benchmarks.robotsim;

import java.util.concurrent.atomic.AtomicLongArray;

/** Request latencies in 10 µs buckets up to 1 s (one overflow bucket); safe to record from several threads. */
final class LatencyHistogram {
    private static final long BUCKET_NANOS = 10_000;
    private static final int BUCKETS = 100_000;
    private final AtomicLongArray counts = new AtomicLongArray(BUCKETS + 1);

    void record(long nanos) {
        long b = nanos / BUCKET_NANOS;
        counts.incrementAndGet((int) Math.min(b, BUCKETS));
    }

    void reset() {
        for (int i = 0; i < counts.length(); i++) {
            counts.set(i, 0);
        }
    }

    /** The latency (ms) below which the given fraction of requests fell; NaN when nothing was recorded. */
    double percentileMillis(double fraction) {
        long total = 0;
        for (int i = 0; i < counts.length(); i++) {
            total += counts.get(i);
        }
        if (total == 0) {
            return Double.NaN;
        }
        long wanted = (long) Math.ceil(total * fraction);
        long seen = 0;
        for (int i = 0; i < counts.length(); i++) {
            seen += counts.get(i);
            if (seen >= wanted) {
                return (i + 1) * BUCKET_NANOS / 1e6;
            }
        }
        return BUCKETS * BUCKET_NANOS / 1e6;
    }
}
