package eu.brain.iot.bip.smc.engine;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.sim.SystemSimulator;
import eu.brain.iot.bip.smc.stats.Bounds;
import eu.brain.iot.bip.smc.stats.Sprt;

/**
 * Answers queries on a simulated system: an estimate (Okamoto count, Clopper–Pearson interval at 1 − δ) for
 * {@code P=?}, a test (SPRT or fixed sample, interval at 1 − α) for {@code P>=θ} and {@code P<=θ}, at every point of
 * each query's sweep. Used by the CLI, the Maven goal and the benchmark. Not thread-safe (it starts its own
 * sampling threads per point).
 */
public final class SmcRunner {

    /** Traces an SPRT may use before it gives up (it stops long before for any δ' &ge; 0.001). */
    static final long SPRT_LIMIT = 100_000_000L;

    /** Progress of one point (for the terminal). */
    public interface Listener {
        /** @param target the traces the point needs, or -1 when a sequential test decides */
        void progress(Query query, double[] params, long done, long target, long successes, long elapsedNanos);

        default void finished(PointResult result) {
        }
    }

    private final SystemSimulator simulator;
    private final List<Query> queries;
    private final SmcOptions options;

    /** @param queries the queries the simulator was made for, in the same order */
    public SmcRunner(SystemSimulator simulator, List<Query> queries, SmcOptions options) {
        this.simulator = simulator;
        this.queries = List.copyOf(queries);
        this.options = options;
    }

    /** @return the results of every point of query {@code q} */
    public List<PointResult> run(int q, Listener listener) throws TraceFailureException, InterruptedException {
        List<PointResult> results = new ArrayList<>();
        for (double[] point : queries.get(q).points()) {
            PointResult r = point(q, point, listener);
            results.add(r);
            if (listener != null) {
                listener.finished(r);
            }
        }
        return results;
    }

    /** @return the results of every query, in order */
    public List<PointResult> runAll(Listener listener) throws TraceFailureException, InterruptedException {
        List<PointResult> all = new ArrayList<>();
        for (int q = 0; q < queries.size(); q++) {
            all.addAll(run(q, listener));
        }
        return all;
    }

    /** Answers query {@code q} at one point of its sweep. */
    public PointResult point(int q, double[] params, Listener listener) throws TraceFailureException,
            InterruptedException {
        Query query = queries.get(q);
        Sampler sampler = new Sampler(simulator, q, query, params, options.seed(), options.effectiveThreads(),
                options.maxSteps());
        if (!query.qualitative()) {
            long n = Bounds.okamoto(options.epsilon(), options.delta());
            Sampler.Totals t = sampler.run(n, s -> false, progress(listener, query, params, n));
            double[] ci = Bounds.clopperPearson(t.successes(), t.samples(), options.delta());
            return new PointResult(query, params, "Okamoto/Clopper-Pearson", t.samples(), t.successes(),
                    (double) t.successes() / t.samples(), ci[0], ci[1], 1 - options.delta(), null, t.undecided(),
                    t.steps(), t.nanos());
        }
        boolean atLeast = query.kind() == Query.Kind.AT_LEAST;
        double theta = atLeast ? query.threshold() : 1 - query.threshold();
        Sampler.Totals t;
        boolean holds;
        String method;
        if (options.test() == SmcOptions.Test.SPRT) {
            Sprt sprt = new Sprt(theta, options.indifference(), options.alpha(), options.beta());
            t = sampler.run(SPRT_LIMIT, s -> sprt.add(atLeast == s) != Sprt.Decision.UNDECIDED,
                    progress(listener, query, params, -1));
            holds = sprt.decision() == Sprt.Decision.ACCEPT_H0;
            method = sprt.decision() == Sprt.Decision.UNDECIDED ? "SPRT (undecided after " + t.samples() + ")"
                    : "SPRT";
        } else {
            long n = (long) Math.ceil(Math.log(1 / Math.min(options.alpha(), options.beta()))
                    / (2 * options.indifference() * options.indifference()));
            t = sampler.run(n, s -> false, progress(listener, query, params, n));
            double p = (double) t.successes() / t.samples();
            holds = atLeast ? p >= query.threshold() : p <= query.threshold();
            method = "fixed-sample test";
        }
        double[] ci = Bounds.clopperPearson(t.successes(), t.samples(), options.alpha());
        return new PointResult(query, params, method, t.samples(), t.successes(), (double) t.successes() / t.samples(),
                ci[0], ci[1], 1 - options.alpha(), holds, t.undecided(), t.steps(), t.nanos());
    }

    private static Sampler.Progress progress(Listener listener, Query query, double[] params, long target) {
        return listener == null ? null
                : (done, successes, elapsed) -> listener.progress(query, params, done, target, successes, elapsed);
    }
}
