package eu.brain.iot.bip.smc.runtime;

/**
 * The random source of one trace (SplitMix64): the scheduler's uniform choice among enabled interactions and the
 * stochastic built-in functions draw from it, in execution order, so a trace is a function of its seed alone. Trace
 * {@code i} of a run with seed {@code s} is seeded with {@link #traceSeed(long, long)}, whatever thread samples it.
 * Owned by one thread (the one sampling the trace).
 */
public final class TraceRandom {

    private static final long GOLDEN = 0x9E3779B97F4A7C15L;

    private long state;

    public void seed(long seed) {
        this.state = seed;
    }

    /** @return the seed of trace {@code index} of a run seeded with {@code seed} */
    public static long traceSeed(long seed, long index) {
        return mix(seed ^ mix(index * GOLDEN + 0x632BE59BD9B4E019L));
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    public long nextLong() {
        return mix(state += GOLDEN);
    }

    /** @return an int in [0, n) (n &ge; 1); the bias of the multiply-shift is below n / 2^32 */
    public int nextInt(int n) {
        return (int) (((nextLong() >>> 32) * n) >>> 32);
    }

    /** @return a double in [0, 1) */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }

    /** Built-in {@code uniform(lo, hi)}: an int in [lo, hi], each with probability 1 / (hi - lo + 1). */
    public int uniform(int lo, int hi) {
        if (hi < lo) {
            throw new StochasticException("uniform(" + lo + ", " + hi + "): the upper bound is below the lower one");
        }
        long span = (long) hi - lo + 1;
        return (int) (lo + Long.remainderUnsigned(nextLong(), span));
    }

    /** Built-in {@code uniformReal(lo, hi)}: a float in [lo, hi). */
    public double uniformReal(double lo, double hi) {
        if (!(hi >= lo)) {
            throw new StochasticException("uniformReal(" + lo + ", " + hi + "): the upper bound is below the lower one");
        }
        return lo + nextDouble() * (hi - lo);
    }

    /** Built-in {@code bernoulli(p)}: true with probability p. */
    public boolean bernoulli(double p) {
        if (!(p >= 0 && p <= 1)) {
            throw new StochasticException("bernoulli(" + p + "): p is not a probability (0 to 1)");
        }
        return nextDouble() < p;
    }
}
