package eu.brain.iot.edge.impl;

import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.LongAdder;

/**
 * Counters of the polling loop, for the Gogo command and the benchmark. A poll is <em>on time</em> when it was
 * answered and its request went out within the period &plusmn; 10% of the previous answered poll's request
 * (500 &plusmn; 50 ms by default). Late, failed and skipped polls (the previous one was still unanswered) are not.
 * <p>
 * The deviations |interval &minus; period| of answered polls are kept in a fixed histogram (0.1 ms buckets up to
 * 10 ms, 1 ms buckets up to 1 s, then one bucket for anything longer), so that percentiles cost one array
 * increment per poll.
 */
final class PollStats {

    private static final long FINE_NANOS = 100_000; // 0.1 ms
    private static final int FINE_BUCKETS = 100; // up to 10 ms
    private static final long COARSE_NANOS = 1_000_000; // 1 ms
    private static final int COARSE_BUCKETS = 990; // up to 1 s
    private static final int BUCKETS = FINE_BUCKETS + COARSE_BUCKETS + 1; // the last: 1 s or more

    private final LongAdder sent = new LongAdder();
    private final LongAdder answered = new LongAdder();
    private final LongAdder failed = new LongAdder();
    private final LongAdder skipped = new LongAdder();
    private final LongAdder onTime = new LongAdder();
    private final LongAdder late = new LongAdder();
    private final AtomicLongArray deviations = new AtomicLongArray(BUCKETS);
    private volatile long since = System.nanoTime();

    /**
     * @param snapshot          the counters and the time they cover
     * @param deviationP50Millis median of |interval &minus; period| over answered polls with a known interval
     *                          (upper edge of its bucket), 0 when none
     * @param deviationP99Millis its 99th percentile
     */
    record Snapshot(long sent, long answered, long failed, long skipped, long onTime, long late, double seconds,
            double deviationP50Millis, double deviationP99Millis) {

        double pollsPerSecond() {
            return seconds <= 0 ? 0 : answered / seconds;
        }

        /** Share of due polls that were answered on time, 0..1. */
        double onTimeShare() {
            long due = onTime + late + failed + skipped;
            return due == 0 ? 1.0 : (double) onTime / due;
        }
    }

    void sent() {
        sent.increment();
    }

    void skipped() {
        skipped.increment();
    }

    void failed() {
        failed.increment();
    }

    /** @param intervalNanos time since the previous answered poll's request, or a negative value when unknown */
    void answered(long intervalNanos, long periodNanos) {
        answered.increment();
        if (intervalNanos < 0) {
            return;
        }
        long deviation = Math.abs(intervalNanos - periodNanos);
        if (deviation <= periodNanos / 10) {
            onTime.increment();
        } else {
            late.increment();
        }
        deviations.incrementAndGet(bucket(deviation));
    }

    private static int bucket(long deviationNanos) {
        if (deviationNanos < FINE_NANOS * FINE_BUCKETS) {
            return (int) (deviationNanos / FINE_NANOS);
        }
        long coarse = (deviationNanos - FINE_NANOS * FINE_BUCKETS) / COARSE_NANOS;
        return (int) Math.min(FINE_BUCKETS + coarse, BUCKETS - 1);
    }

    /** The upper edge of a bucket, in milliseconds (the last bucket has none: its lower edge). */
    private static double upperMillis(int bucket) {
        if (bucket < FINE_BUCKETS) {
            return (bucket + 1) * FINE_NANOS / 1e6;
        }
        if (bucket == BUCKETS - 1) {
            return (FINE_NANOS * FINE_BUCKETS + COARSE_NANOS * COARSE_BUCKETS) / 1e6;
        }
        return (FINE_NANOS * FINE_BUCKETS + (bucket - FINE_BUCKETS + 1) * COARSE_NANOS) / 1e6;
    }

    private static double deviationPercentileMillis(long[] counts, long total, double quantile) {
        if (total == 0) {
            return 0;
        }
        long rank = (long) Math.ceil(quantile * total);
        long seen = 0;
        for (int i = 0; i < counts.length; i++) {
            seen += counts[i];
            if (seen >= rank) {
                return upperMillis(i);
            }
        }
        return upperMillis(BUCKETS - 1);
    }

    Snapshot snapshot() {
        long[] counts = new long[BUCKETS];
        long total = 0;
        for (int i = 0; i < BUCKETS; i++) {
            counts[i] = deviations.get(i);
            total += counts[i];
        }
        return new Snapshot(sent.sum(), answered.sum(), failed.sum(), skipped.sum(), onTime.sum(), late.sum(),
                (System.nanoTime() - since) / 1e9, deviationPercentileMillis(counts, total, 0.50),
                deviationPercentileMillis(counts, total, 0.99));
    }

    /** Start counting afresh (a benchmark's measured window). */
    void reset() {
        sent.reset();
        answered.reset();
        failed.reset();
        skipped.reset();
        onTime.reset();
        late.reset();
        for (int i = 0; i < BUCKETS; i++) {
            deviations.set(i, 0);
        }
        since = System.nanoTime();
    }
}
