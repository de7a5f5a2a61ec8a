package eu.brain.iot.benchmarks.fabric;

import java.util.Arrays;

/** Percentiles of latency samples in nanoseconds. */
record LatencyStats(int samples, long p50Nanos, long p99Nanos, long maxNanos) {

    static LatencyStats of(long[] nanos, int count) {
        if (count == 0) {
            return new LatencyStats(0, 0, 0, 0);
        }
        long[] sorted = Arrays.copyOf(nanos, count);
        Arrays.sort(sorted);
        return new LatencyStats(count, percentile(sorted, 0.50), percentile(sorted, 0.99), sorted[count - 1]);
    }

    private static long percentile(long[] sorted, double q) {
        int index = (int) Math.ceil(q * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, index))];
    }

    static String millis(long nanos) {
        return String.format(java.util.Locale.ROOT, "%.2f", nanos / 1e6);
    }
}
