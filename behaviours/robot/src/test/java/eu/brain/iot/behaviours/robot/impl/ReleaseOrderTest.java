package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/** Which waiting robot goes for a cart first: nearest a door by path when released continuously, else as asked. */
class ReleaseOrderTest {

    /**
     * Docks along the top row, a wall with one door at (5,3) below. The dock at (1,1) is four cells from (5,1) as the
     * crow flies, yet (5,1) is two steps from the door and (1,1) six.
     */
    private static final Grid DOCKS = Grid.parse(String.join("\n",
            "###########",
            "#R.R.R.R.R#",
            "#.........#",
            "#####D#####",
            "#uuuuuuuuu#",
            "###########"));

    private static final Cell FAR = new Cell(1, 1);
    private static final Cell MIDDLE = new Cell(3, 1);
    private static final Cell ABOVE_THE_DOOR = new Cell(5, 1);
    private static final long FRESH = 2_000;

    private final AtomicLong now = new AtomicLong(1_000_000);
    private final ReleaseOrder nearest = ReleaseOrder.nearestDoorFirst(FRESH, now::get);

    @Test
    void withOneRobotFreeTheOneNearestTheDoorGoesAndTheOthersWait() {
        assertThat(nearest.mayGo("robot1", FAR, 1, DOCKS)).as("alone so far").isTrue();
        assertThat(nearest.mayGo("robot3", ABOVE_THE_DOOR, 1, DOCKS)).isTrue();
        assertThat(nearest.mayGo("robot2", MIDDLE, 1, DOCKS)).as("robot3 is nearer the door").isFalse();
        assertThat(nearest.mayGo("robot1", FAR, 1, DOCKS)).as("robot3 and robot2 are nearer").isFalse();
        assertThat(nearest.mayGo("robot1", FAR, 3, DOCKS)).as("room for all three").isTrue();
    }

    @Test
    void aRobotThatClaimedNoLongerWaitsAndTheNextNearestGoes() {
        nearest.mayGo("robot1", FAR, 1, DOCKS);
        nearest.mayGo("robot2", MIDDLE, 1, DOCKS);
        assertThat(nearest.mayGo("robot3", ABOVE_THE_DOOR, 1, DOCKS)).isTrue();
        nearest.went("robot3");
        assertThat(nearest.mayGo("robot1", FAR, 1, DOCKS)).as("robot2 is nearer").isFalse();
        assertThat(nearest.mayGo("robot2", MIDDLE, 1, DOCKS)).isTrue();
    }

    @Test
    void aRobotThatStoppedAskingHoldsNobodyBack() {
        nearest.mayGo("robot3", ABOVE_THE_DOOR, 1, DOCKS); // then its carts are used up: it never asks again
        now.addAndGet(FRESH + 1);
        assertThat(nearest.mayGo("robot1", FAR, 1, DOCKS)).isTrue();
    }

    @Test
    void tiesGoByNameAndNobodyGoesWhenNoneMay() {
        Cell left = new Cell(3, 1);
        Cell right = new Cell(7, 1); // four steps from the door, as (3,1) is
        assertThat(nearest.mayGo("robot4", left, 1, DOCKS)).isTrue();
        assertThat(nearest.mayGo("robot5", right, 1, DOCKS)).as("as near as robot4, named after it").isFalse();
        assertThat(nearest.mayGo("robot4", left, 0, DOCKS)).as("the door policy has no room").isFalse();
    }

    @Test
    void asAskedEveryRobotGoesWhileThereIsRoom() {
        ReleaseOrder asAsked = ReleaseOrder.asAsked();
        assertThat(asAsked.mayGo("robot3", ABOVE_THE_DOOR, 1, DOCKS)).isTrue();
        assertThat(asAsked.mayGo("robot1", FAR, 1, DOCKS)).as("the wave's order, not the distance").isTrue();
        assertThat(asAsked.mayGo("robot1", FAR, 0, DOCKS)).isFalse();
    }
}
