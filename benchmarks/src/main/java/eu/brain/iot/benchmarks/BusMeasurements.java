package eu.brain.iot.benchmarks;

import java.io.Serializable;
import java.util.Arrays;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import eu.brain.iot.benchmarks.spi.BusDriver;
import eu.brain.iot.benchmarks.spi.ConsumerProbe;

/**
 * Measures one bus through its driver, on the calling thread, which is the single publisher.
 * <p>
 * Throughput: a round publishes N events back to back and ends when every consumer has counted all N (end to end,
 * not publish rate). N is calibrated per bus so that a round lasts about {@link Settings#roundMillis()}.
 * Latency: events are paced at {@link Settings#latencyRate()}; each consumer records its receive time minus the
 * publish time carried in the event; all consumers' samples are pooled.
 */
final class BusMeasurements {

    private static final int MIN_ROUND_EVENTS = 5_000;
    private static final int MAX_ROUND_EVENTS = 5_000_000;
    private static final long ROUND_DEADLINE_SECONDS = 120;

    private final BusDriver driver;
    private final Settings settings;

    BusMeasurements(BusDriver driver, Settings settings) {
        this.driver = driver;
        this.settings = settings;
    }

    /**
     * Events per second of each measured round, in round order, and what the whole process spent on them.
     *
     * @param cost CPU time and context switches of all measured rounds together
     */
    record Throughput(int events, double[] rounds, ProcessCost cost) implements Serializable {
        double cpuMicrosPerEvent() {
            return cost.cpuNanos() / 1_000.0 / ((double) events * rounds.length);
        }

        double switchesPerEvent() {
            return (cost.voluntarySwitches() + cost.involuntarySwitches()) / ((double) events * rounds.length);
        }

        double median() {
            double[] sorted = rounds.clone();
            Arrays.sort(sorted);
            int m = sorted.length / 2;
            return sorted.length % 2 == 1 ? sorted[m] : (sorted[m - 1] + sorted[m]) / 2;
        }

        double min() {
            return Arrays.stream(rounds).min().orElse(Double.NaN);
        }

        double max() {
            return Arrays.stream(rounds).max().orElse(Double.NaN);
        }
    }

    /** Pooled latency samples of every consumer, sorted, in nanoseconds. */
    record Latency(long[] sortedNanos, double achievedRate) implements Serializable {
        double meanMicros() {
            return Arrays.stream(sortedNanos).average().orElse(Double.NaN) / 1_000.0;
        }

        double percentileMicros(double p) {
            int index = (int) Math.ceil(p / 100.0 * sortedNanos.length) - 1;
            return sortedNanos[Math.max(0, Math.min(index, sortedNanos.length - 1))] / 1_000.0;
        }

        double maxMicros() {
            return sortedNanos[sortedNanos.length - 1] / 1_000.0;
        }
    }

    Throughput throughput(int consumers) throws Exception {
        ConsumerProbe[] probes = probes(consumers);
        try (AutoCloseable registrations = driver.registerConsumers(probes)) {
            awaitFirstEvent(probes);
            int events = calibrate(probes);
            for (int i = 0; i < settings.warmupRounds(); i++) {
                burst(probes, events);
            }
            double[] rounds = new double[settings.rounds()];
            ProcessCost cost = ProcessCost.zero();
            for (int i = 0; i < rounds.length; i++) {
                ProcessCost before = ProcessCost.now();
                rounds[i] = burst(probes, events);
                cost = cost.plus(ProcessCost.now().since(before));
            }
            return new Throughput(events, rounds, cost);
        }
    }

    Latency latency(int consumers) throws Exception {
        ConsumerProbe[] probes = probes(consumers);
        long interval = TimeUnit.SECONDS.toNanos(1) / settings.latencyRate();
        try (AutoCloseable registrations = driver.registerConsumers(probes)) {
            awaitFirstEvent(probes);
            int warmup = settings.latencyRate() * settings.latencyWarmupSeconds();
            if (warmup > 0) {
                paced(probes, warmup, interval, null);
            }
            int events = settings.latencyRate() * settings.latencySeconds();
            long[][] samples = new long[consumers][events];
            long start = System.nanoTime();
            paced(probes, events, interval, samples);
            double rate = events * 1e9 / (System.nanoTime() - start);
            long[] pooled = Arrays.stream(samples).flatMapToLong(Arrays::stream).sorted().toArray();
            return new Latency(pooled, rate);
        }
    }

    private static ConsumerProbe[] probes(int consumers) {
        ConsumerProbe[] probes = new ConsumerProbe[consumers];
        Arrays.setAll(probes, i -> new ConsumerProbe());
        return probes;
    }

    /** Every consumer must take part: registration is synchronous on all three buses, so the first event counts. */
    private void awaitFirstEvent(ConsumerProbe[] probes) throws InterruptedException {
        CountDownLatch done = arm(probes, 1, null);
        driver.publishBurst(1);
        await(done, probes, 1, 10);
    }

    /**
     * Find how many events make a round of about {@link Settings#roundMillis()}: at least three bursts (they warm the
     * bus up too), each at least as long as the one before, until one lasts a quarter of a round; the count is then
     * scaled by the rate measured last.
     */
    private int calibrate(ConsumerProbe[] probes) throws InterruptedException {
        long events = MIN_ROUND_EVENTS;
        double rate = 0;
        for (int i = 0; i < 3 || events * 1_000.0 / rate * 4 < settings.roundMillis(); i++) {
            if (i == 12 || events >= MAX_ROUND_EVENTS) {
                break;
            }
            rate = burst(probes, (int) events);
            events = Math.max(events, clampRound(rate * settings.roundMillis() / 1_000.0 / 4));
        }
        return clampRound(rate * settings.roundMillis() / 1_000.0);
    }

    private static int clampRound(double events) {
        return (int) Math.max(MIN_ROUND_EVENTS, Math.min(MAX_ROUND_EVENTS, events));
    }

    /** @return events per second, from the first publish until the last consumer counted the last event */
    private double burst(ConsumerProbe[] probes, int events) throws InterruptedException {
        CountDownLatch done = arm(probes, events, null);
        long start = System.nanoTime();
        driver.publishBurst(events);
        await(done, probes, events, ROUND_DEADLINE_SECONDS);
        return events * 1e9 / (System.nanoTime() - start);
    }

    private void paced(ConsumerProbe[] probes, int events, long interval, long[][] samples)
            throws InterruptedException {
        CountDownLatch done = new CountDownLatch(probes.length);
        for (int i = 0; i < probes.length; i++) {
            probes[i].arm(events, done, samples == null ? null : samples[i]);
        }
        driver.publishPaced(events, interval);
        await(done, probes, events, ROUND_DEADLINE_SECONDS);
    }

    private static CountDownLatch arm(ConsumerProbe[] probes, long target, long[] samples) {
        CountDownLatch done = new CountDownLatch(probes.length);
        for (ConsumerProbe probe : probes) {
            probe.arm(target, done, samples);
        }
        return done;
    }

    private static void await(CountDownLatch done, ConsumerProbe[] probes, long events, long seconds)
            throws InterruptedException {
        if (!done.await(seconds, TimeUnit.SECONDS)) {
            throw new BenchmarkException("consumers did not count all " + events + " events within " + seconds
                    + " s; counts: " + Arrays.toString(Arrays.stream(probes).mapToLong(ConsumerProbe::received)
                            .toArray()) + ". The bus lost, duplicated or stalled events.");
        }
        for (ConsumerProbe probe : probes) {
            if (probe.received() != events) {
                throw new BenchmarkException("a consumer counted " + probe.received() + " events of " + events
                        + ": the bus delivered some events twice.");
            }
        }
    }
}
