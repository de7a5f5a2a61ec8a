package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;

class FiguresTest {

    @Test
    void quantilesOfWaitLengthsTakeTheNearestRank() {
        TreeMap<Long, Long> h = new TreeMap<>(java.util.Map.of(1L, 5L, 4L, 3L, 20L, 1L));
        assertThat(Figures.quantile(h, 0.5)).isEqualTo(1);
        assertThat(Figures.quantile(h, 0.8)).isEqualTo(4);
        assertThat(Figures.quantile(h, 1.0)).isEqualTo(20);
        assertThat(Figures.quantile(new TreeMap<>(), 0.5)).isZero();
    }

    @Test
    void waitShareIsRobotStepsWaitingOverRobotStepsAndWaitsCountOnlyDuringTheRun() throws Exception {
        try (Fleet f = Fleet.paper()) {
            f.goTo("robot1", 9, 1); // robot2 at (4,1) is in the way from the second step on
            f.step(3);
            f.goTo("robot2", 4, 3);
            f.step(3);
            WorldSnapshot start = f.world();
            f.goTo("robot1", 2, 1);
            f.goTo("robot2", 3, 1); // now robot2 waits behind robot1 at (3,1)... until robot1 leaves for (2,1)
            f.step(10);
            WorldSnapshot end = f.world();
            long robotSteps = 10 * 3;
            assertThat(Figures.waitShare(start, end))
                    .isCloseTo((double) (end.waitSteps() - start.waitSteps()) / robotSteps, within(1e-9));
            assertThat(Figures.elapsedMs(start, end)).isEqualTo(5_000);
            assertThat(start.endedWaits()).isNotEmpty();
            long before = start.endedWaits().values().stream().mapToLong(Long::longValue).sum();
            long after = end.endedWaits().values().stream().mapToLong(Long::longValue).sum();
            assertThat(Figures.waits(start, end).values().stream().mapToLong(Long::longValue).sum())
                    .isEqualTo(after - before);
        }
    }

    @Test
    void oneDoorBoundsTheCartsPerHour() {
        // one robot at a time, alternating: 4 steps (2 s) per passage, 2 passages per cart: 900 carts/h
        assertThat(Figures.doorBoundCartsPerHour(1, 1, 500)).isCloseTo(900, within(1e-6));
        // long batches per direction approach 2 steps per passage: 1,800 carts/h
        assertThat(Figures.doorBoundCartsPerHour(1, 30, 500)).isCloseTo(1_800 * 30 / 31.0, within(1e-6));
        assertThat(Figures.doorBoundCartsPerHour(2, 1, 500)).isCloseTo(1_800, within(1e-6));
        assertThat(Figures.cartsPerHour(3, 180_000)).isCloseTo(60, within(1e-9));
    }

    @Test
    void longDetailsAreCutInTheTerminalAtAListSeparator() {
        String many = String.join(", ", java.util.Collections.nCopies(60, "cart12 at (12,23)"));
        String cut = Summary.shorten(many);
        assertThat(cut).endsWith("cart12 at (12,23), ... (the whole list is in the report)");
        assertThat(cut.length()).isLessThan(Summary.DETAIL_CHARS + 50);
        assertThat(Summary.shorten("3/3 carts in storage")).isEqualTo("3/3 carts in storage");
    }

    @Test
    void busStatsAreReadFromTheShellsTable() {
        BusStats s = BusStats.parse(List.of(
                "EVENT TYPE                                                      PUBLISHED    DELIVERED   FAILED  "
                        + "UNHANDLED  DISCARDED     HELD",
                "eu.brain.iot.edge.api.RobotPositionChanged                            120          240        0  "
                        + "         0          0        0",
                "eu.brain.iot.edge.api.GoToCommand                                      12           12        0  "
                        + "         0          0        0",
                "eu.brain.iot.edge.api.OpenDoorCommand                                   2            2        0  "
                        + "         0          0        0",
                "eu.brain.iot.edge.api.CommandOutcome                                   14           14        0  "
                        + "         0          0        0",
                "BEHAVIOUR                                BUNDLE                             QUEUED    DELIVERED   FAILED  "
                        + "CONSUMES",
                "sensiNact edge#33                        eu.brain.iot.edge.impl                  0            0        0"
                        + "  eu.brain.iot.edge.api.EdgeCommand"));
        assertThat(s.totalPublished()).isEqualTo(148);
        assertThat(s.commandsPublished()).isEqualTo(14);
        assertThat(s.outcomesPublished()).isEqualTo(14);
    }
}
