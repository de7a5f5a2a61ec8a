package eu.brain.iot.bip.smc;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.smc.query.Monitor;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.query.QueryException;
import eu.brain.iot.bip.smc.stats.Bounds;

/** PBLTL parsing, resolution errors with positions, bounded LTL semantics of the monitor, and the bounds. */
class QueryTest {

    private static SmcSession warehouse;

    @BeforeAll
    static void load() {
        warehouse = SmcModels.load(SmcModels.WAREHOUSE);
    }

    @Test
    void queriesParseWithPrecedenceSweepsAndHorizon() throws Exception {
        Query q = warehouse.parse("P>=0.25 [ G<=10 (R1.x + 1 > 2 => X R1 at L) && R1.c <= x U<=5 sched at T1 ] "
                + "for x = 0:3:1, y = 0.5:1:0.25");
        assertThat(q.kind()).isEqualTo(Query.Kind.AT_LEAST);
        assertThat(q.threshold()).isEqualTo(0.25);
        assertThat(q.propositions()).hasSize(4);
        assertThat(q.points()).hasSize(4 * 3);
        assertThat(q.horizon(new double[] {0, 0})).isEqualTo(11);
        assertThat(warehouse.parse("P<=0.1 [ F<=1000 R1.c + R2.c + R3.c >= 20 ]").kind()).isEqualTo(Query.Kind.AT_MOST);
        assertThat(warehouse.parse("P=? [ F<=k R1.c >= 1 ] for k = 0:100:50").horizon(new double[] {50}))
                .isEqualTo(50);
        assertThat(warehouse.parse("P=? [ (R1.x) * 2 == 8 and not false ]").propositions()).hasSize(1);
    }

    private static void fails(String query, int column, String... messages) {
        assertThatThrownBy(() -> warehouse.parse(null, query, new Pos("--property", 1, 1), ""))
                .isInstanceOf(QueryException.class)
                .satisfies(e -> {
                    assertThat(((QueryException) e).pos().column()).isEqualTo(column);
                    for (String m : messages) {
                        assertThat(e.getMessage()).contains(m);
                    }
                    assertThat(e.toString()).startsWith("--property:1:" + column + ": error: ");
                });
    }

    @Test
    void badQueriesNameWhatIsWrongAndWhatExists() {
        fails("P=? [ F<=10 R9.x == 1 ]", 13, "unknown component R9", "components: sched, R1, R2, R3");
        fails("P=? [ F<=10 R1.speed == 1 ]", 16, "component R1 (Robot) has no data speed", "data: ux, uy");
        fails("P=? [ F<=10 R1 at DOOR ]", 19, "has no place DOOR", "places: L");
        fails("P=? [ F<=10 R1.x == z ]", 21, "unknown name z", "for x = from:to:step");
        fails("P>=1.5 [ true ]", 4, "not a probability");
        fails("P=? [ F<=10 R1.x ]", 13, "expected a condition");
        fails("P=? [ F<=10 R1.x == 1 ", 23, "expected ']'");
        fails("Q=? [ true ]", 1, "a query starts with P");
        fails("P=? [ F<=k true ] for k = 0.5:2:0.5", 10, "step bound");
    }

    /** Runs the monitor on a trace of proposition valuations (one bit per proposition); @return 1, 0 or -1 */
    private static int decide(String formula, int... states) throws Exception {
        Query q = warehouse.parse("P=? [ " + formula + " ]");
        Monitor m = new Monitor(q.formula(), q.propositions().size(), new double[0]);
        int r = -1;
        for (int i = 0; r < 0; i++) {
            int s = states[Math.min(i, states.length - 1)];
            r = m.observe(p -> (s >> p & 1) != 0);
            if (i > 100) {
                break;
            }
        }
        return r;
    }

    @Test
    void theMonitorFollowsBoundedLtl() throws Exception {
        // p0 is R1.x == 1, p1 is R2.x == 1 (bits of each state)
        assertThat(decide("F<=2 R1.x == 1", 0, 0, 1)).isEqualTo(1);
        assertThat(decide("F<=2 R1.x == 1", 0, 0, 0, 1)).isEqualTo(0);
        assertThat(decide("G<=2 R1.x == 1", 1, 1, 1, 0)).isEqualTo(1);
        assertThat(decide("G<=2 R1.x == 1", 1, 0, 1)).isEqualTo(0);
        assertThat(decide("X R1.x == 1", 0, 1)).isEqualTo(1);
        assertThat(decide("X X R1.x == 1", 1, 1, 0)).isEqualTo(0);
        assertThat(decide("R1.x == 1 U<=3 R2.x == 1", 1, 1, 2)).isEqualTo(1);
        assertThat(decide("R1.x == 1 U<=3 R2.x == 1", 1, 0, 2)).isEqualTo(0);
        assertThat(decide("R1.x == 1 U<=1 R2.x == 1", 1, 1, 2)).isEqualTo(0);
        assertThat(decide("G<=3 (R1.x == 1 => F<=1 R2.x == 1)", 1, 2, 0, 1, 2)).isEqualTo(1);
        assertThat(decide("G<=3 (R1.x == 1 => F<=1 R2.x == 1)", 0, 1, 0, 0)).isEqualTo(0);
        assertThat(decide("!(F<=1 R1.x == 1) || R2.x == 1", 0, 0)).isEqualTo(1);
    }

    @Test
    void atADeadlockTheMonitorDecidesAsIfTheLastStateRepeated() throws Exception {
        String[] formulas = {"F<=5 R1.x == 1", "G<=5 R1.x == 1", "R1.x == 1 U<=4 R2.x == 1", "X X R2.x == 1",
            "G<=4 (R1.x == 1 => F<=2 R2.x == 1)", "!(R2.x == 1) && F<=3 (R1.x == 1 && X R2.x == 1)"};
        for (String f : formulas) {
            Query q = warehouse.parse("P=? [ " + f + " ]");
            for (int prefix = 0; prefix < 16; prefix++) {
                for (int last = 0; last < 4; last++) {
                    int[] trace = {prefix & 3, prefix >> 2, last};
                    Monitor fed = new Monitor(q.formula(), q.propositions().size(), new double[0]);
                    Monitor collapsed = new Monitor(q.formula(), q.propositions().size(), new double[0]);
                    int expected = -1;
                    for (int i = 0; expected < 0; i++) {
                        int s = trace[Math.min(i, 2)];
                        expected = fed.observe(p -> (s >> p & 1) != 0);
                    }
                    int actual = -1;
                    for (int i = 0; i < 2 && actual < 0; i++) {
                        int s = trace[i];
                        actual = collapsed.observe(p -> (s >> p & 1) != 0);
                    }
                    if (actual < 0) {
                        int repeated = last;
                        actual = collapsed.decideOnRepeatedState(p -> (repeated >> p & 1) != 0);
                    }
                    assertThat(actual).as("%s on %d %d %d...", f, trace[0], trace[1], last).isEqualTo(expected);
                }
            }
        }
    }

    @Test
    void okamotoAndClopperPearson() {
        assertThat(Bounds.okamoto(0.01, 0.01)).isEqualTo(26492);
        double[] ci = Bounds.clopperPearson(0, 10, 0.05);
        assertThat(ci[0]).isZero();
        assertThat(ci[1]).isCloseTo(1 - Math.pow(0.025, 0.1), org.assertj.core.data.Offset.offset(1e-9));
        double[] mid = Bounds.clopperPearson(50, 100, 0.05);
        assertThat(mid[0]).isCloseTo(0.3983, org.assertj.core.data.Offset.offset(1e-4));
        assertThat(mid[1]).isCloseTo(0.6017, org.assertj.core.data.Offset.offset(1e-4));
    }
}
