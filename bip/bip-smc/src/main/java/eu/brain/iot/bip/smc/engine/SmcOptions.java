package eu.brain.iot.bip.smc.engine;

import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * How queries are checked.
 *
 * @param epsilon estimation: half-width of the interval (Okamoto count)
 * @param delta estimation: 1 − confidence
 * @param alpha tests: P(refuting a requirement that holds with margin δ')
 * @param beta tests: P(accepting a requirement that fails by margin δ')
 * @param indifference tests: δ', half-width of the indifference region around θ
 * @param test how thresholds are tested
 * @param seed the run's seed (trace i uses a seed derived from it and i)
 * @param threads sampling threads (0: every core)
 * @param maxSteps trace length limit (0: each formula's horizon)
 * @param engine compiled (default) or interpreted
 */
public record SmcOptions(double epsilon, double delta, double alpha, double beta, double indifference, Test test,
        long seed, int threads, int maxSteps, SystemSimulator.Engine engine) {

    /** Sequential (Wald) or with the fixed sample count {@code ln(1/min(α,β)) / (2δ'²)}. */
    public enum Test { SPRT, FIXED }

    public static SmcOptions defaults() {
        return new SmcOptions(0.01, 0.01, 0.01, 0.01, 0.01, Test.SPRT, 1, 0, 0, SystemSimulator.Engine.COMPILED);
    }

    public int effectiveThreads() {
        return threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    /** @return a problem with the values, or null */
    public String problem() {
        if (!(epsilon > 0 && epsilon < 0.5)) {
            return "epsilon must be in (0, 0.5), found " + epsilon;
        }
        for (double v : new double[] {delta, alpha, beta}) {
            if (!(v > 0 && v < 0.5)) {
                return "delta, alpha and beta must be in (0, 0.5), found " + v;
            }
        }
        if (!(indifference > 0 && indifference < 0.5)) {
            return "the indifference region's half-width must be in (0, 0.5), found " + indifference;
        }
        if (threads < 0 || maxSteps < 0) {
            return "threads and max-steps cannot be negative";
        }
        return null;
    }

    public SmcOptions withSeed(long s) {
        return new SmcOptions(epsilon, delta, alpha, beta, indifference, test, s, threads, maxSteps, engine);
    }

    public SmcOptions withThreads(int t) {
        return new SmcOptions(epsilon, delta, alpha, beta, indifference, test, seed, t, maxSteps, engine);
    }

    public SmcOptions withEngine(SystemSimulator.Engine e) {
        return new SmcOptions(epsilon, delta, alpha, beta, indifference, test, seed, threads, maxSteps, e);
    }

    /** The option names {@link #with} knows. */
    public static final String KEYS = "epsilon, delta, alpha, beta, indifference, test (sprt|fixed), seed, threads, "
            + "max-steps, engine (compiled|interpreted)";

    /**
     * @return these options with one changed by name (as in a requirements file's {@code set} or a CLI option)
     * @throws IllegalArgumentException naming what is wrong
     */
    public SmcOptions with(String key, String value) {
        try {
            SmcOptions o = switch (key) {
                case "epsilon" -> new SmcOptions(Double.parseDouble(value), delta, alpha, beta, indifference, test, seed,
                        threads, maxSteps, engine);
                case "delta" -> new SmcOptions(epsilon, Double.parseDouble(value), alpha, beta, indifference, test, seed,
                        threads, maxSteps, engine);
                case "alpha" -> new SmcOptions(epsilon, delta, Double.parseDouble(value), beta, indifference, test, seed,
                        threads, maxSteps, engine);
                case "beta" -> new SmcOptions(epsilon, delta, alpha, Double.parseDouble(value), indifference, test, seed,
                        threads, maxSteps, engine);
                case "indifference" -> new SmcOptions(epsilon, delta, alpha, beta, Double.parseDouble(value), test,
                        seed, threads, maxSteps, engine);
                case "test" -> new SmcOptions(epsilon, delta, alpha, beta, indifference,
                        Test.valueOf(value.toUpperCase(java.util.Locale.ROOT)), seed, threads, maxSteps, engine);
                case "seed" -> withSeed(Long.parseLong(value));
                case "threads" -> withThreads(Integer.parseInt(value));
                case "max-steps" -> new SmcOptions(epsilon, delta, alpha, beta, indifference, test, seed, threads,
                        Integer.parseInt(value), engine);
                case "engine" -> withEngine(SystemSimulator.Engine.valueOf(value.toUpperCase(java.util.Locale.ROOT)));
                default -> throw new IllegalArgumentException("unknown option " + key + " (options: " + KEYS + ")");
            };
            String problem = o.problem();
            if (problem != null) {
                throw new IllegalArgumentException(problem);
            }
            return o;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("option " + key + " needs a number, found '" + value + "'");
        } catch (IllegalArgumentException e) {
            if (e.getMessage() != null && e.getMessage().startsWith("No enum constant")) {
                throw new IllegalArgumentException("option " + key + ": unknown value '" + value + "' (" + KEYS + ")");
            }
            throw e;
        }
    }
}
