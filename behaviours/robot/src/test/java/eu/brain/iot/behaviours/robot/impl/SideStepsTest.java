package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.RobotState;

/** A robot told to step aside keeps to its side cell while the robot it let pass comes by, and no longer. */
class SideStepsTest {

    private final Map<String, RobotState> robots = new HashMap<>();
    private final Function<String, Optional<RobotState>> view = id -> Optional.ofNullable(robots.get(id));

    @Test
    void itDrivesThereThenWaitsWhileThePasserIsNearAndMovingThenGoesOn() {
        SideSteps aside = new SideSteps(Long.MAX_VALUE);
        aside.told("robot1", new Cell(3, 2), "robot2");
        assertThat(aside.holds(robot("robot1", new Cell(3, 3), true), view)).as("on its way").isTrue();
        put(robot("robot2", new Cell(3, 4), true));
        assertThat(aside.holds(robot("robot1", new Cell(3, 2), false), view)).as("the passer comes by").isTrue();
        put(robot("robot2", new Cell(3, 6), true));
        assertThat(aside.holds(robot("robot1", new Cell(3, 2), false), view)).as("the passer is gone").isFalse();
        assertThat(aside.holds(robot("robot1", new Cell(3, 2), false), view)).as("forgotten").isFalse();
    }

    @Test
    void aPasserThatStopsNearbyOrNoPasserAtAllIsNotWaitedFor() {
        SideSteps noWait = new SideSteps(-1); // any time aside is longer than that
        noWait.told("robot1", new Cell(3, 2), "robot2");
        put(robot("robot2", new Cell(3, 3), true));
        assertThat(noWait.holds(robot("robot1", new Cell(3, 2), false), view)).as("waited long enough").isFalse();
        SideSteps aside = new SideSteps(Long.MAX_VALUE);
        aside.told("robot1", new Cell(3, 2), null);
        assertThat(aside.holds(robot("robot1", new Cell(3, 2), false), view)).isFalse();
        aside.told("robot1", new Cell(3, 2), "robot2");
        put(robot("robot2", new Cell(3, 3), false));
        assertThat(aside.holds(robot("robot1", new Cell(3, 2), false), view)).as("the passer stopped").isFalse();
    }

    private void put(RobotState s) {
        robots.put(s.id(), s);
    }

    private static RobotState robot(String id, Cell cell, boolean moving) {
        return new RobotState(id, cell, "N", 0, moving, RobotState.DETECTS_NOTHING, null, 1L, RobotState.GOTO,
                moving ? "running" : RobotState.FINISHED, moving ? new Cell(0, 0) : null, true);
    }
}
