package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;

/** How robots are released towards the doors: in waves, or continuously under the traffic planner. */
class CartReleaseTest {

    @Test
    void aWaveClosesWhenFullAndStaysClosedWhileOneOfItsRobotsCarriesACart() {
        CartRelease waves = CartRelease.waves(4);
        assertThat(waves.open(0, 0, 1)).isTrue();
        assertThat(waves.open(3, 0, 1)).isTrue();
        assertThat(waves.open(4, 0, 1)).as("the wave is full").isFalse();
        assertThat(waves.open(0, 1, 1)).as("a robot of the wave carries its cart back").isFalse();
        assertThat(waves.open(4, 0, 3)).as("a wave does not grow with the doors").isFalse();
        assertThat(waves.order(1)).isEqualTo(CartChoice.Order.NEAREST);
    }

    @Test
    void releasedContinuouslyARobotSetsOffWhileFewerThanItsShareOfTheDoorsAreOutOnErrands() {
        CartRelease continuous = CartRelease.continuous(20);
        assertThat(continuous.open(0, 1, 1)).isTrue();
        assertThat(continuous.open(19, 0, 1)).as("as many going for carts as the door's share").isTrue();
        assertThat(continuous.open(20, 0, 1)).as("20 robots per door").isFalse();
        assertThat(continuous.open(5, 14, 1)).isTrue();
        assertThat(continuous.open(5, 15, 1)).as("20 robots out through one door: going for carts or carrying")
                .isFalse();
        assertThat(continuous.open(30, 29, 3)).isTrue();
        assertThat(continuous.open(30, 30, 3)).as("60 robots out through three doors, whatever the fleet's size")
                .isFalse();
        assertThat(continuous.open(19, 0, 0)).as("a map without a door counts as one").isTrue();
        assertThat(continuous.order(1)).as("through one door").isEqualTo(CartChoice.Order.FARTHEST);
        assertThat(continuous.order(3)).as("the farthest is through another door")
                .isEqualTo(CartChoice.Order.DEEPEST_BEHIND_NEAREST_DOOR);
    }

    @Test
    void aReleaseLetsAtLeastOneRobotGo() {
        assertThat(CartRelease.waves(0).open(0, 0, 1)).isTrue();
        assertThat(CartRelease.waves(0).open(1, 0, 1)).isFalse();
        assertThat(CartRelease.continuous(0).open(0, 0, 1)).isTrue();
        assertThat(CartRelease.continuous(0).open(0, 1, 1)).as("one robot per door, out already").isFalse();
    }

    @Test
    void inWavesACarrierSetsOffOnceTheWavesOtherRobotsAreDownOrBehindACarrier() {
        CartRelease waves = CartRelease.waves(4);
        Errands.Errand goingDown = new Errands.Errand("robot2", Errands.Leg.TO_CART, "cart2", new Cell(5, 8), null,
                new Cell(2, 1));
        RobotState carrier = robot("robot1", new Cell(5, 5), Grid.CORRIDOR, RobotState.DETECTS_NOTHING, "cart1");
        RobotState onTheWay = robot("robot2", new Cell(5, 3), Grid.CORRIDOR, RobotState.DETECTS_NOTHING, null);
        RobotState down = robot("robot2", new Cell(5, 8), Grid.UNLOAD, RobotState.DETECTS_NOTHING, null);
        RobotState behind = robot("robot2", new Cell(5, 4), Grid.CORRIDOR, RobotState.DETECTS_ROBOT, null);
        List<RobotState> others = List.of(robot("robot3", new Cell(1, 1), Grid.DOCKING, 0, null),
                robot("robot4", new Cell(2, 1), Grid.DOCKING, 0, null));

        assertThat(waves.mayCarryBack("robot1", List.of(goingDown), with(carrier, onTheWay, others)))
                .as("robot2 still comes down").isFalse();
        assertThat(waves.mayCarryBack("robot1", List.of(goingDown), with(carrier, down, others))).isTrue();
        assertThat(waves.mayCarryBack("robot1", List.of(goingDown), with(carrier, behind, others)))
                .as("robot2 waits behind the carrier, which must move first").isTrue();
        assertThat(waves.mayCarryBack("robot1", List.of(goingDown), List.of(carrier, onTheWay)))
                .as("one group: the orchestrator resolves meetings at the door").isTrue();
        assertThat(CartRelease.continuous(20).mayCarryBack("robot1", List.of(goingDown),
                with(carrier, onTheWay, others))).as("the planner's reservations order the door").isTrue();
    }

    private static List<RobotState> with(RobotState a, RobotState b, List<RobotState> rest) {
        return Stream.concat(Stream.of(a, b), rest.stream()).toList();
    }

    private static RobotState robot(String id, Cell cell, int area, int detect, String cart) {
        return new RobotState(id, cell, "S", area, detect == RobotState.DETECTS_NOTHING, detect, cart, 1L,
                RobotState.GOTO, "running", new Cell(5, 8), true);
    }
}
