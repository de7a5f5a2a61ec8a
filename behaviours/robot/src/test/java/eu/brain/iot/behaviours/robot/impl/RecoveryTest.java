package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Optional;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.robot.impl.Recovery.Fix;
import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;

/** The binding's recovery step: which disagreement between a robot and its errand gets which fix, and none else. */
class RecoveryTest {

    private static final Cell CART = new Cell(5, 8);
    private static final Cell DROP = new Cell(5, 3);
    private static final Cell DOCK = new Cell(2, 1);

    @Test
    void aRobotTakenOverCarryingItsCartGoesThroughCartAgainWhateverElseHolds() {
        RobotState carrying = robot(CART, true, "cart1");
        assertThat(fix(carrying, errand(Errands.Leg.TO_CART, DROP), false, true, true)).contains(Fix.THROUGH_CART);
        assertThat(fix(carrying, errand(Errands.Leg.TO_STORAGE, DROP), false, false, false))
                .contains(Fix.THROUGH_CART);
        assertThat(fix(robot(CART, false, "cart1"), errand(Errands.Leg.TO_STORAGE, DROP), true, false, false))
                .as("the model knows it carries, and it drives on: on its errand").isEmpty();
    }

    @Test
    void aCartOnTheFloorNoStorageCellYetOrIdleBeforeItsGoalMakeItGoOn() {
        RobotState idleEmpty = robot(new Cell(5, 5), true, null);
        assertThat(step(idleEmpty, errand(Errands.Leg.TO_STORAGE, DROP), true, true, false))
                .map(Recovery.Step::why).contains("carrying nothing");
        RobotState idleCarrying = robot(new Cell(5, 5), true, "cart1");
        assertThat(step(idleCarrying, errand(Errands.Leg.TO_STORAGE, null), true, false, false))
                .map(Recovery.Step::why).contains("looking for a free storage cell");
        assertThat(step(idleCarrying, errand(Errands.Leg.TO_STORAGE, DROP), true, false, false))
                .map(Recovery.Step::why).contains("idle before its goal");
        assertThat(step(idleEmpty, errand(Errands.Leg.NONE, null), false, false, true))
                .as("no errand while a cart waits").map(Recovery.Step::why).contains("idle before its goal");
    }

    @Test
    void aRobotOnItsErrandIsLeftToTheNormalMoves() {
        assertThat(fix(robot(new Cell(5, 5), false, null), errand(Errands.Leg.TO_CART, null), false, false, true))
                .as("moving").isEmpty();
        assertThat(fix(robot(CART, true, null), errand(Errands.Leg.TO_CART, null), false, false, true))
                .as("at its cart: the normal move lifts it").isEmpty();
        assertThat(fix(robot(DROP, true, "cart1"), errand(Errands.Leg.TO_STORAGE, DROP), true, false, true))
                .as("at its storage cell").isEmpty();
        assertThat(fix(robot(DOCK, true, null), errand(Errands.Leg.NONE, null), false, false, false))
                .as("no errand, no cart waiting").isEmpty();
    }

    @Test
    void goingHomeOnlyAnIdleRobotAwayFromItsDockGoesOn() {
        assertThat(Recovery.homeward(robot(new Cell(2, 3), true, null), errand(Errands.Leg.TO_DOCK, null)))
                .map(Recovery.Step::fix).contains(Fix.GO_ON);
        assertThat(Recovery.homeward(robot(DOCK, true, null), errand(Errands.Leg.TO_DOCK, null))).isEmpty();
        assertThat(Recovery.homeward(robot(new Cell(2, 3), false, null), errand(Errands.Leg.TO_DOCK, null)))
                .isEmpty();
    }

    @Test
    void aRobotGoingHomeWithItsCartIdleAndNoPlaceToShowCarriesItBack() {
        RobotState withCart = robot(new Cell(2, 3), true, "cart1");
        Errands.Errand home = errand(Errands.Leg.TO_DOCK, null);
        assertThat(Recovery.carryingHome(withCart, home, () -> false)).map(Recovery.Step::fix)
                .contains(Fix.CARRY_BACK);
        assertThat(Recovery.carryingHome(withCart, home, () -> false)).map(Recovery.Step::why)
                .contains("going home carrying cart1");
        assertThat(Recovery.inUnload(withCart, home, false, () -> false, () -> true, () -> false))
                .as("in UNLOAD too (home after a resolved meeting)").map(Recovery.Step::fix).contains(Fix.CARRY_BACK);
        assertThat(Recovery.carryingHome(withCart, home, () -> true)).as("its place still to show").isEmpty();
        assertThat(Recovery.carryingHome(robot(new Cell(2, 3), false, "cart1"), home, () -> false))
                .as("moving: the place may run before the go-to home").isEmpty();
        assertThat(Recovery.carryingHome(robot(new Cell(2, 3), true, null), home, () -> false)).as("empty")
                .isEmpty();
        assertThat(Recovery.carryingHome(withCart, errand(Errands.Leg.TO_STORAGE, DROP), () -> false))
                .as("carrying to storage").isEmpty();
    }

    private static Optional<Fix> fix(RobotState s, Errands.Errand e, boolean modelCarrying, boolean cartOnFloor,
            boolean workLeft) {
        return step(s, e, modelCarrying, cartOnFloor, workLeft).map(Recovery.Step::fix);
    }

    private static Optional<Recovery.Step> step(RobotState s, Errands.Errand e, boolean modelCarrying,
            boolean cartOnFloor, boolean workLeft) {
        return Recovery.inUnload(s, e, modelCarrying, () -> cartOnFloor, () -> workLeft, () -> false);
    }

    private static Errands.Errand errand(Errands.Leg leg, Cell drop) {
        return new Errands.Errand("robot1", leg, leg == Errands.Leg.NONE ? null : "cart1",
                leg == Errands.Leg.NONE ? null : CART, drop, DOCK);
    }

    private static RobotState robot(Cell cell, boolean idle, String cart) {
        return new RobotState("robot1", cell, "N", Grid.UNLOAD, !idle, RobotState.DETECTS_NOTHING, cart, 1L,
                RobotState.GOTO, idle ? RobotState.FINISHED : "running", idle ? null : CART, true);
    }
}
