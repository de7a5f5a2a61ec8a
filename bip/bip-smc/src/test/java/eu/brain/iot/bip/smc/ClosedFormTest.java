package eu.brain.iot.bip.smc;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * Estimates and tests on models whose answers are known exactly: every estimate within ε of the exact value, the
 * failure rate over repeated seeds consistent with δ, and SPRT accepting and rejecting around known thresholds
 * with its stated error rates.
 */
class ClosedFormTest {

    /** Gambler's ruin from 3 on 0..6 with p = 0.4: (1 − r³) / (1 − r⁶), r = 1.5 (absorption by 1,000 steps is sure
     *  up to 1e-60). */
    static final double RUIN = (1 - Math.pow(1.5, 3)) / (1 - Math.pow(1.5, 6));

    private static SmcSession walk;
    private static SmcSession dice;
    private static SmcSession chain;

    @BeforeAll
    static void load() {
        walk = SmcModels.load("RandomWalk");
        dice = SmcModels.load("KnuthYao");
        chain = SmcModels.load("BirthDeath");
    }

    /** Compiled once per query: the runs differ only in their options. */
    private static final java.util.Map<String, Object[]> COMPILED = new java.util.HashMap<>();

    private static List<PointResult> run(SmcSession s, String query, SmcOptions o) throws Exception {
        Object[] entry = COMPILED.get(s.system().root().name() + query);
        if (entry == null) {
            Query q = s.parse(query);
            entry = new Object[] {q, s.simulator(List.of(q), o, () -> SimulationExterns.NONE, List.of())};
            COMPILED.put(s.system().root().name() + query, entry);
        }
        Query q = (Query) entry[0];
        return s.runner((SystemSimulator) entry[1], List.of(q), o).run(0, null);
    }

    private static SmcOptions options(double epsilon, double delta, long seed) {
        return SmcOptions.defaults().with("epsilon", "" + epsilon).with("delta", "" + delta).withSeed(seed)
                .withThreads(2);
    }

    @Test
    void estimatesAreWithinEpsilonOfTheExactValues() throws Exception {
        SmcOptions o = options(0.01, 0.01, 11);
        assertThat(run(walk, "P=? [ F<=1000 w.x == 6 ]", o).get(0).estimate()).isCloseTo(RUIN,
                org.assertj.core.data.Offset.offset(0.01));
        List<PointResult> faces = run(dice, "P=? [ F<=200 die.d == f ] for f = 1:6:1", o);
        assertThat(faces).hasSize(6).allSatisfy(r -> assertThat(r.estimate()).isCloseTo(1 / 6.0,
                org.assertj.core.data.Offset.offset(0.01)));
        double exact = BirthDeathExact.probabilityOfVisits(2, 40);
        PointResult r = run(chain, "P=? [ F<=40 pop.visits >= 2 ]", o).get(0);
        assertThat(r.estimate()).isCloseTo(exact, org.assertj.core.data.Offset.offset(0.01));
        assertThat(r.samples()).isEqualTo(26492);
        assertThat(r.lower()).isLessThanOrEqualTo(exact);
        assertThat(r.upper()).isGreaterThanOrEqualTo(exact);
    }

    @Test
    void theFailureRateOverSeedsIsConsistentWithDelta() throws Exception {
        // ε = 0.05, δ = 0.2: at most 20% of the runs may miss; Hoeffding is conservative, so far fewer do. 40 runs:
        // more than 16 misses would have probability below 0.1% if the rate were 0.2.
        int misses = 0;
        double exact = BirthDeathExact.probabilityOfVisits(1, 20);
        for (int seed = 1; seed <= 40; seed++) {
            PointResult r = run(chain, "P=? [ F<=20 pop.visits >= 1 ]", options(0.05, 0.2, seed)).get(0);
            if (Math.abs(r.estimate() - exact) >= 0.05) {
                misses++;
            }
        }
        assertThat(misses).isLessThanOrEqualTo(16);
    }

    @Test
    void sprtAcceptsAndRejectsAroundTheExactValueWithinItsErrorRates() throws Exception {
        // RUIN ≈ 0.2286; indifference 0.02, α = β = 0.05: thresholds 0.18 (holds) and 0.28 (refuted) lie outside
        // the indifference region, so each wrong answer has probability at most 0.05.
        int wrong = 0;
        long samples = 0;
        for (int seed = 1; seed <= 20; seed++) {
            SmcOptions o = SmcOptions.defaults().with("alpha", "0.05").with("beta", "0.05")
                    .with("indifference", "0.02").withSeed(seed).withThreads(2);
            PointResult holds = run(walk, "P>=0.18 [ F<=1000 w.x == 6 ]", o).get(0);
            PointResult refuted = run(walk, "P>=0.28 [ F<=1000 w.x == 6 ]", o).get(0);
            PointResult atMost = run(walk, "P<=0.28 [ F<=1000 w.x == 6 ]", o).get(0);
            wrong += (holds.verdict() ? 0 : 1) + (refuted.verdict() ? 1 : 0) + (atMost.verdict() ? 0 : 1);
            samples += holds.samples() + refuted.samples();
            assertThat(holds.method()).isEqualTo("SPRT");
        }
        // 60 tests at error rate <= 0.05: more than 9 wrong has probability below 0.2%
        assertThat(wrong).isLessThanOrEqualTo(9);
        // the sequential test stops early: far fewer samples than the fixed test's ln(1/0.05)/(2·0.02²) = 3745
        assertThat(samples / 40).isLessThan(3745);
    }

    @Test
    void theFixedSampleTestUsesItsSampleCount() throws Exception {
        SmcOptions o = SmcOptions.defaults().with("test", "fixed").with("indifference", "0.05").withThreads(2);
        PointResult r = run(walk, "P>=0.18 [ F<=1000 w.x == 6 ]", o).get(0);
        assertThat(r.verdict()).isTrue();
        assertThat(r.samples()).isEqualTo((long) Math.ceil(Math.log(100) / (2 * 0.05 * 0.05)));
    }

    @Test
    void aSeedGivesTheSameAnswerWhateverTheNumberOfThreads() throws Exception {
        SmcOptions o = options(0.02, 0.05, 99);
        PointResult one = run(chain, "P=? [ F<=40 pop.visits >= 2 ]", o.withThreads(1)).get(0);
        PointResult three = run(chain, "P=? [ F<=40 pop.visits >= 2 ]", o.withThreads(3)).get(0);
        assertThat(three.successes()).isEqualTo(one.successes());
        assertThat(three.steps()).isEqualTo(one.steps());
        SmcOptions t = SmcOptions.defaults().withSeed(5);
        PointResult s1 = run(walk, "P>=0.22 [ F<=1000 w.x == 6 ]", t.withThreads(1)).get(0);
        PointResult s3 = run(walk, "P>=0.22 [ F<=1000 w.x == 6 ]", t.withThreads(3)).get(0);
        assertThat(s3.samples()).isEqualTo(s1.samples());
        assertThat(s3.verdict()).isEqualTo(s1.verdict());
    }
}
