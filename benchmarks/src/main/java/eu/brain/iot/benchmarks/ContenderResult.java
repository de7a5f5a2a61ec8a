package eu.brain.iot.benchmarks;

import java.io.Serializable;

/**
 * What was measured for one contender; a failed contender has an error and no figures.
 *
 * @param bundles the bundles that ran, with versions
 */
record ContenderResult(Contender contender, String bundles, BusMeasurements.Throughput eight,
        BusMeasurements.Throughput one, BusMeasurements.Latency latency, String error) implements Serializable {

    static ContenderResult failed(Contender contender, String error) {
        return new ContenderResult(contender, "", null, null, null, error);
    }
}
