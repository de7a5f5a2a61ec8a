package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;

/** A robot standing on one cell with an errand is reported once, after {@link StandingWatch#LOOKS} looks. */
class StandingWatchTest {

    private static final Cell HERE = new Cell(75, 8);
    private static final Errands.Errand CARRYING = new Errands.Errand("robot38", Errands.Leg.TO_STORAGE, "cart181",
            new Cell(90, 33), new Cell(75, 6), new Cell(75, 1));
    private static final List<String> UNLOAD = List.of("UNLOAD");

    @Test
    void reportedOnceAfterItsLooksWithWhatItWaitsFor() {
        StandingWatch watch = new StandingWatch();
        for (int i = 1; i < StandingWatch.LOOKS; i++) {
            assertThat(watch.look("robot38", HERE, CARRYING, UNLOAD)).as("look %d", i).isEmpty();
        }
        Optional<String> line = watch.look("robot38", HERE, CARRYING, UNLOAD);
        assertThat(line).hasValueSatisfying(l -> assertThat(l).contains("robot38", "(75,8)", "TO_STORAGE",
                "cart181", "storage cell (75,6)", "[UNLOAD]"));
        assertThat(watch.look("robot38", HERE, CARRYING, UNLOAD)).as("once per stand").isEmpty();
    }

    @Test
    void aMoveAChangeOfPlacesOrNoErrandStartsAgain() {
        StandingWatch watch = new StandingWatch();
        for (int i = 1; i < StandingWatch.LOOKS; i++) {
            watch.look("robot38", HERE, CARRYING, UNLOAD);
        }
        assertThat(watch.look("robot38", new Cell(75, 7), CARRYING, UNLOAD)).as("it moved").isEmpty();
        for (int i = 1; i < StandingWatch.LOOKS; i++) {
            watch.look("robot38", HERE, CARRYING, UNLOAD);
        }
        assertThat(watch.look("robot38", HERE, CARRYING, List.of("ROBOT"))).as("its model moved on").isEmpty();
        Errands.Errand none = new Errands.Errand("robot38", Errands.Leg.NONE, null, null, null, new Cell(75, 1));
        for (int i = 0; i < 2 * StandingWatch.LOOKS; i++) {
            assertThat(watch.look("robot38", HERE, none, UNLOAD)).as("docked without an errand").isEmpty();
        }
    }
}
