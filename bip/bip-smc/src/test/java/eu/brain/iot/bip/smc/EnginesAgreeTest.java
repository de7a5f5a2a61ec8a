package eu.brain.iot.bip.smc;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.runtime.SimulatedSystem;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * The compiled engine (deployed atom classes + generated driver) and the interpreter produce the same traces of
 * whole systems for the same seeds: the same step chosen, the same places and data after every step, the same
 * atomic propositions, the same deadlocks.
 */
class EnginesAgreeTest {

    private static final String[][] MODELS = {
        {"prism-warehouse/Warehouse3", "P=? [ F<=10 R1.c >= 1 && R2 at L || R3.x + R3.y * 2 > 7 ]"},
        {"RandomWalk", "P=? [ F<=10 w.x == 6 ]"},
        {"KnuthYao", "P=? [ F<=10 die.d == 3 && die at DONE ]"},
        {"BirthDeath", "P=? [ F<=10 pop.visits >= 1 && env at L ]"},
        {"Mixed", "P=? [ F<=10 snd.w > 2.5 && rc1.got % 3 == 1 || rc2 at BUSY || n1 at P3 ]"},
        {"Subset", "P=? [ F<=10 O.rounds >= 2 && O.a > 3 || R2.reports >= 2 && R1 at READY ]"},
    };

    @ParameterizedTest
    @ValueSource(ints = {0, 1, 2, 3, 4, 5})
    void sampledTracesAreIdentical(int model) throws Exception {
        SmcSession session = SmcModels.load(SmcModels.DIR.resolve(MODELS[model][0] + ".bip"));
        Query q = session.parse(MODELS[model][1]);
        SimulatedSystem compiled = SystemSimulator.of(session.system(), List.of(q), SystemSimulator.Engine.COMPILED,
                () -> SimulationExterns.NONE, List.of()).create(0, new double[0]);
        SimulatedSystem interpreted = SystemSimulator.of(session.system(), List.of(q),
                SystemSimulator.Engine.INTERPRETED, () -> SimulationExterns.NONE, List.of()).create(0, new double[0]);
        int steps = 0;
        for (int trace = 0; trace < 30; trace++) {
            long seed = TraceRandom.traceSeed(42, trace);
            compiled.reset(seed);
            interpreted.reset(seed);
            assertThat(compiled.state()).isEqualTo(interpreted.state());
            for (int i = 0; i < 200; i++) {
                boolean c = compiled.step();
                boolean r = interpreted.step();
                assertThat(c).as("trace %d step %d: deadlock", trace, i).isEqualTo(r);
                if (!c) {
                    break;
                }
                steps++;
                assertThat(compiled.lastStep()).as("trace %d step %d", trace, i).isEqualTo(interpreted.lastStep());
                assertThat(compiled.state()).as("trace %d step %d after %s", trace, i, compiled.lastStep())
                        .isEqualTo(interpreted.state());
                for (int p = 0; p < q.propositions().size(); p++) {
                    assertThat(compiled.ap(p)).isEqualTo(interpreted.ap(p));
                }
            }
        }
        assertThat(steps).as("the traces are not trivial").isGreaterThan(100);
    }
}
