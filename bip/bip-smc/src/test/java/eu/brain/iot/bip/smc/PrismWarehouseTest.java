package eu.brain.iot.bip.smc;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * The BIP version of the PRISM warehouse benchmark (Warehouse3.bip) agrees with the reference values of PRISM's
 * chain (BENCHMARKS.md, "Statistical model checking", from 2,000,000 traces): each 99% interval overlaps the
 * reference's 99% interval.
 */
class PrismWarehouseTest {

    /** query, reference value, half-width of the reference's 99% interval. */
    private static final Object[][] REFERENCE = {
        {"P=? [ F<=1000 R1.x == 9 && R1.y >= 3 ]", 1.0, 0.0},
        {"P=? [ (R1.y == 0 && R1.x <= 2) U<=1000 (R1.x == 9 && R1.y >= 3) ]", 0.0, 0.0},
        {"P=? [ F<=1000 R1.c >= 4 ]", 0.9872, 0.0002},
        {"P=? [ F<=1000 R1.c >= 6 ]", 0.5703, 0.0009},
        {"P=? [ F<=1000 R1.c >= 8 ]", 0.3675, 0.0009},
        {"P=? [ F<=1000 R1.c >= 10 ]", 0.2997, 0.0008},
        {"P=? [ F<=1000 R1.c >= 12 ]", 0.0, 0.0},
        {"P=? [ F<=1000 R1.c + R2.c + R3.c >= 20 ]", 0.4986, 0.0009},
    };

    @Test
    void everyEstimateAgreesWithThePrismReference() throws Exception {
        SmcSession s = SmcModels.load(SmcModels.WAREHOUSE);
        List<Query> queries = new ArrayList<>();
        for (Object[] r : REFERENCE) {
            queries.add(s.parse((String) r[0]));
        }
        SmcOptions o = SmcOptions.defaults().withSeed(2026);
        SystemSimulator sim = s.simulator(queries, o, () -> SimulationExterns.NONE, List.of());
        List<PointResult> results = s.runner(sim, queries, o).runAll(null);
        for (int i = 0; i < REFERENCE.length; i++) {
            PointResult r = results.get(i);
            double ref = (Double) REFERENCE[i][1];
            double half = (Double) REFERENCE[i][2];
            assertThat(r.samples()).isEqualTo(26492);
            assertThat(r.upper()).as("%s: [%f, %f] vs %f", r.query().text(), r.lower(), r.upper(), ref)
                    .isGreaterThanOrEqualTo(ref - half);
            assertThat(r.lower()).as("%s: [%f, %f] vs %f", r.query().text(), r.lower(), r.upper(), ref)
                    .isLessThanOrEqualTo(ref + half);
        }
        // a trace of the headline query is about 982 steps long, as in PRISM's simulator
        assertThat(results.get(5).steps() / 26492.0).isBetween(970.0, 995.0);
    }
}
