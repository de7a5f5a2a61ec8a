package eu.brain.iot.bip.smc.engine;

import java.util.HashMap;
import java.util.Map;
import java.util.function.IntPredicate;

import eu.brain.iot.bip.smc.query.Monitor;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.runtime.SimulatedSystem;
import eu.brain.iot.bip.smc.runtime.TraceRandom;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * Samples traces 0, 1, 2, ... of one query at one sweep point on several threads, and hands their results to a
 * consumer in trace order (so a sequential test decides the same whatever the thread count). Threads take chunks
 * of 64 consecutive traces; trace i is seeded with {@link TraceRandom#traceSeed}(seed, i).
 * <p>
 * Threads: the workers own their simulated system and monitor; finished chunks go into {@code done}, guarded by
 * {@code lock}, which the calling thread (the only consumer) drains in order. {@code next} (the next chunk to hand
 * out), {@code stop} and {@code failure} are guarded by {@code lock} too.
 */
final class Sampler {

    static final int CHUNK = 64;

    /** The results of 64 consecutive traces. */
    private record Chunk(long successes, long undecided, long steps, int count) {
    }

    /** Receives trace results in order; returns true to stop sampling. */
    interface Consumer {
        boolean accept(boolean success);
    }

    /** Told now and then (from the consuming thread) how far sampling got. */
    interface Progress {
        void update(long done, long successes, long elapsedNanos);
    }

    record Totals(long samples, long successes, long undecided, long steps, long nanos) {
    }

    private final SystemSimulator simulator;
    private final int queryIndex;
    private final Query query;
    private final double[] params;
    private final long seed;
    private final int threads;
    private final int maxSteps;
    private final Object lock = new Object();
    private final Map<Long, Chunk> done = new HashMap<>();
    private final Map<Long, long[]> bits = new HashMap<>();
    private long next;
    private long limitChunks;
    private boolean stop;
    private TraceFailureException failure;

    Sampler(SystemSimulator simulator, int queryIndex, Query query, double[] params, long seed, int threads,
            int maxSteps) {
        this.simulator = simulator;
        this.queryIndex = queryIndex;
        this.query = query;
        this.params = params;
        this.seed = seed;
        this.threads = threads;
        this.maxSteps = maxSteps;
    }

    /**
     * Samples until the consumer stops or {@code limit} traces were consumed.
     */
    Totals run(long limit, Consumer consumer, Progress progress) throws TraceFailureException, InterruptedException {
        long start = System.nanoTime();
        limitChunks = (limit + CHUNK - 1) / CHUNK;
        Thread[] workers = new Thread[threads];
        for (int t = 0; t < threads; t++) {
            workers[t] = new Thread(() -> work(limit), "smc-sampler-" + t);
            workers[t].setDaemon(true);
            workers[t].start();
        }
        long consumed = 0;
        long successes = 0;
        long undecided = 0;
        long steps = 0;
        long lastProgress = start;
        try {
            outer:
            for (long c = 0; c < limitChunks; c++) {
                Chunk chunk;
                long[] b;
                synchronized (lock) {
                    while ((chunk = done.remove(c)) == null && failure == null) {
                        lock.wait(100);
                        long now = System.nanoTime();
                        if (progress != null && now - lastProgress > 200_000_000L) {
                            lastProgress = now;
                            progress.update(consumed, successes, now - start);
                        }
                    }
                    if (failure != null) {
                        throw failure;
                    }
                    b = bits.remove(c);
                }
                undecided += chunk.undecided();
                steps += chunk.steps();
                for (int i = 0; i < chunk.count(); i++) {
                    boolean success = (b[0] >>> i & 1L) != 0;
                    consumed++;
                    if (success) {
                        successes++;
                    }
                    if (consumer.accept(success)) {
                        break outer;
                    }
                }
                long now = System.nanoTime();
                if (progress != null && now - lastProgress > 200_000_000L) {
                    lastProgress = now;
                    progress.update(consumed, successes, now - start);
                }
            }
        } finally {
            synchronized (lock) {
                stop = true;
                lock.notifyAll();
            }
            for (Thread w : workers) {
                w.join();
            }
        }
        return new Totals(consumed, successes, undecided, steps, System.nanoTime() - start);
    }

    /**
     * Samples one trace until the monitor knows the formula's value, the trace deadlocks or {@code max} steps.
     * A small method of its own, so that the JIT compiles this loop early and on its own.
     *
     * @return the result (1 holds, 0 does not, -1 undecided) in the high 32 bits, the steps taken in the low ones
     */
    private static long trace(SimulatedSystem system, Monitor monitor, IntPredicate aps, long seed, int max) {
        system.reset(seed);
        monitor.reset();
        int position = 0;
        int taken = 0;
        int r;
        while ((r = monitor.observe(aps)) < 0) {
            if (position == max) {
                break;
            }
            position++;
            if (system.step()) {
                taken++;
            } else {
                r = monitor.decideOnRepeatedState(aps);
                break;
            }
        }
        return ((long) r << 32) | (taken & 0xFFFFFFFFL);
    }

    private void work(long limit) {
        SimulatedSystem system = simulator.create(queryIndex, params);
        Monitor monitor = new Monitor(query.formula(), query.propositions().size(), params);
        int offset = simulator.apOffset(queryIndex);
        IntPredicate aps = i -> system.ap(offset + i);
        int max = maxSteps > 0 ? maxSteps : query.horizon(params);
        while (true) {
            long c;
            synchronized (lock) {
                if (stop || next >= limitChunks) {
                    return;
                }
                c = next++;
            }
            long first = c * CHUNK;
            int count = (int) Math.min(CHUNK, limit - first);
            long word = 0;
            long undecided = 0;
            long steps = 0;
            long trace = first;
            try {
                for (int i = 0; i < count; i++) {
                    trace = first + i;
                    long outcome = trace(system, monitor, aps, TraceRandom.traceSeed(seed, trace), max);
                    int r = (int) (outcome >> 32);
                    int taken = (int) outcome;
                    if (r == 1) {
                        word |= 1L << i;
                    } else if (r < 0) {
                        undecided++;
                    }
                    steps += taken;
                }
            } catch (RuntimeException | StackOverflowError e) {
                synchronized (lock) {
                    if (failure == null) {
                        String where = system.lastStep().isEmpty() ? "in its initial state"
                                : "at a step after " + system.lastStep();
                        String what = e instanceof eu.brain.iot.bip.smc.runtime.StochasticException ? e.getMessage()
                                : e.toString();
                        failure = new TraceFailureException("trace " + trace + " (run seed " + seed + ") failed "
                                + where + ": " + what, e);
                    }
                    lock.notifyAll();
                }
                return;
            }
            synchronized (lock) {
                done.put(c, new Chunk(Long.bitCount(word), undecided, steps, count));
                bits.put(c, new long[] {word});
                lock.notifyAll();
            }
        }
    }
}
