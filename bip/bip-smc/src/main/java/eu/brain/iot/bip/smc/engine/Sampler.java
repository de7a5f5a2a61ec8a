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
 * A failure of a worker (an exception or an Error of the model's code, of the simulation of its extern functions,
 * or of the compiled classes) ends the run at once with a {@link TraceFailureException}: a failing trace ends its
 * chunk, which carries the failure; the consumer throws it when it reaches that trace (so whether a run fails, and
 * where, depends on the seed only, not on the thread count), and no worker samples beyond it. A failure outside any
 * trace (creating the system) is thrown to the consumer at once. The consumer never waits for a chunk no worker is
 * left to sample.
 * <p>
 * Threads: the workers own their simulated system and monitor; finished chunks go into {@code done}, guarded by
 * {@code lock}, which the calling thread (the only consumer) drains in order. {@code next} (the next chunk to hand
 * out), {@code stop}, {@code failedChunk}, {@code failure} and {@code running} are guarded by {@code lock} too.
 */
final class Sampler {

    static final int CHUNK = 64;

    /**
     * The results of {@code count} consecutive traces (bit i of {@code word}: trace i holds); when {@code failure} is
     * not null, the trace after them failed.
     */
    private record Chunk(long word, long undecided, long steps, int count, TraceFailureException failure) {
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
    private long next;
    private long limitChunks;
    private boolean stop;
    /** The first chunk in which a trace failed: no chunk after it is handed out. */
    private long failedChunk = Long.MAX_VALUE;
    /** A failure outside any trace. */
    private TraceFailureException failure;
    /** Workers that have not returned yet. */
    private int running;

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
     *
     * @throws TraceFailureException when a trace the consumer needs (or the system itself) fails
     */
    Totals run(long limit, Consumer consumer, Progress progress) throws TraceFailureException, InterruptedException {
        long start = System.nanoTime();
        limitChunks = (limit + CHUNK - 1) / CHUNK;
        Thread[] workers = new Thread[threads];
        running = threads;
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
            for (long c = 0; c < limitChunks; c++) {
                Chunk chunk;
                synchronized (lock) {
                    while ((chunk = done.remove(c)) == null) {
                        if (failure != null) {
                            throw failure;
                        }
                        if (running == 0) {
                            // cannot happen while work() catches everything: never wait for a chunk nobody samples
                            throw new TraceFailureException("the sampling threads ended before trace " + c * CHUNK
                                    + " was sampled (an internal error of bip: please report it with the model)",
                                    null);
                        }
                        lock.wait(100);
                        long now = System.nanoTime();
                        if (progress != null && now - lastProgress > 200_000_000L) {
                            lastProgress = now;
                            progress.update(consumed, successes, now - start);
                        }
                    }
                }
                undecided += chunk.undecided();
                steps += chunk.steps();
                boolean stopped = false;
                for (int i = 0; i < chunk.count() && !stopped; i++) {
                    boolean success = (chunk.word() >>> i & 1L) != 0;
                    consumed++;
                    if (success) {
                        successes++;
                    }
                    stopped = consumer.accept(success);
                }
                if (stopped) {
                    break;
                }
                if (chunk.failure() != null) {
                    throw chunk.failure();
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

    /** A worker: samples chunks until there are no more, the consumer stops, or a trace fails. */
    private void work(long limit) {
        try {
            SimulatedSystem system = simulator.create(queryIndex, params);
            Monitor monitor = new Monitor(query.formula(), query.propositions().size(), params);
            int offset = simulator.apOffset(queryIndex);
            IntPredicate aps = i -> system.ap(offset + i);
            int max = maxSteps > 0 ? maxSteps : query.horizon(params);
            while (true) {
                long c;
                synchronized (lock) {
                    if (stop || next >= limitChunks || next > failedChunk) {
                        return;
                    }
                    c = next++;
                }
                if (!sampleChunk(c, limit, system, monitor, aps, max)) {
                    return;
                }
            }
        } catch (Throwable e) { // NOPMD: even an Error (a class that fails to link) must end the run, never hang it
            synchronized (lock) {
                if (failure == null) {
                    failure = new TraceFailureException(TraceFailures.describe(-1, seed, "", e), e);
                }
            }
        } finally {
            synchronized (lock) {
                running--;
                lock.notifyAll();
            }
        }
    }

    /** Samples chunk {@code c} and posts it. @return false when one of its traces failed (the chunk says which) */
    private boolean sampleChunk(long c, long limit, SimulatedSystem system, Monitor monitor, IntPredicate aps,
            int max) {
        long first = c * CHUNK;
        int count = (int) Math.min(CHUNK, limit - first);
        long word = 0;
        long undecided = 0;
        long steps = 0;
        int i = 0;
        TraceFailureException failed = null;
        try {
            for (; i < count; i++) {
                long outcome = trace(system, monitor, aps, TraceRandom.traceSeed(seed, first + i), max);
                int r = (int) (outcome >> 32);
                if (r == 1) {
                    word |= 1L << i;
                } else if (r < 0) {
                    undecided++;
                }
                steps += (int) outcome;
            }
        } catch (Throwable e) { // NOPMD: see work()
            failed = new TraceFailureException(TraceFailures.describe(first + i, seed, system.lastStep(), e), e);
        }
        synchronized (lock) {
            done.put(c, new Chunk(word, undecided, steps, i, failed));
            if (failed != null) {
                failedChunk = Math.min(failedChunk, c);
            }
            lock.notifyAll();
        }
        return failed == null;
    }
}
