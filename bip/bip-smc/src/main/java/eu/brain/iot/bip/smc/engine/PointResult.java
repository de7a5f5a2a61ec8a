package eu.brain.iot.bip.smc.engine;

import eu.brain.iot.bip.smc.query.Query;

/**
 * The answer to a query at one point of its sweep.
 *
 * @param params the swept parameters' values (in the query's sweep order)
 * @param method "Okamoto/Clopper-Pearson", "SPRT" or "fixed-sample test"
 * @param estimate successes / samples
 * @param lower lower end of the Clopper–Pearson interval at {@code confidence}
 * @param upper upper end
 * @param verdict for a test: whether the requirement holds (null for an estimate)
 * @param undecided traces whose value was not known when the trace length limit was reached (counted as false)
 * @param steps steps taken by all traces
 * @param samplingNanos wall time of the sampling
 */
public record PointResult(Query query, double[] params, String method, long samples, long successes, double estimate,
        double lower, double upper, double confidence, Boolean verdict, long undecided, long steps, long samplingNanos) {

    public boolean refuted() {
        return verdict != null && !verdict;
    }
}
