package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;

/**
 * The extern functions leave what they ask of the fleet as steps, per robot and in order, for the node's host; a lift
 * counts against the robot's budget unless the robot carries its cart already; the model alone keeps no steps.
 */
class RobotExternsTest {

    @Test
    void eachRobotsStepsAreKeptInOrderUntilItsHostTakesThem() {
        RobotExterns externs = new RobotExterns();
        externs.bipInstance("g2", "Robot1"); // robot4
        externs.moveTo(1, 2);
        externs.liftCart(1, 3);
        externs.moveTo(1, 0); // not concerned by a resolved collision: nothing
        externs.moveTo(1, -(1 + 4 + 1000 * 2));
        externs.bipInstance("g1", "Robot1");
        externs.placeCart(1);

        assertThat(externs.takeSteps("robot4")).containsExactly(ModelStep.MOVE_ON, ModelStep.LIFT,
                ModelStep.aside(new Cell(4, 2)));
        assertThat(externs.takeSteps("robot4")).as("taken once").isEmpty();
        assertThat(externs.takeSteps("robot1")).containsExactly(ModelStep.PLACE);
    }

    @Test
    void aRobotWhoseHostStoppedTakingItsStepsKeepsOnlyTheLatest() {
        RobotExterns externs = new RobotExterns();
        externs.bipInstance("g1", "Robot1");
        for (int i = 0; i < RobotExterns.MAX_STEPS + 10; i++) {
            externs.moveTo(1, 2);
        }
        externs.placeCart(1);
        assertThat(externs.takeSteps("robot1")).hasSize(RobotExterns.MAX_STEPS).last().isEqualTo(ModelStep.PLACE);
    }

    @Test
    void theModelAloneKeepsNoSteps() {
        RobotExterns externs = RobotExterns.withoutFleet();
        externs.bipInstance("g1", "Robot1");
        externs.moveTo(1, 2);
        externs.placeCart(1);
        assertThat(externs.takeSteps("robot1")).isEmpty();
    }

    @Test
    void aLiftCountsAgainstTheBudgetUnlessTheRobotCarriesItsCartAlready() {
        TrafficControlTest.Model model = new TrafficControlTest.Model();
        model.robot(1, 1, "stopped", 0, null, null);
        RobotExterns externs = new RobotExterns();
        externs.bindDevices(model);
        externs.bipInstance("g1", "Robot1");
        assertThat(externs.liftCart(1, 3)).as("a cart lifted from the floor").isEqualTo(2);

        model.carrying("cart1"); // taken over carrying it, or carrying it back to storage: lifted again
        model.robot(1, 1, "stopped", 0, null, null);
        assertThat(externs.liftCart(1, 2)).as("the cart it carries, counted when first lifted").isEqualTo(2);
        assertThat(externs.takeSteps("robot1")).containsExactly(ModelStep.LIFT, ModelStep.LIFT);
    }

    @Test
    void aRobotIsWhereItsAreaSaysOrInUnloadOutOnTheFloorOrDockedWhenNotSeen() {
        RobotExterns externs = new RobotExterns();
        externs.bipInstance("g1", "Robot1");
        assertThat(externs.getPosition(1)).as("no device model").isEqualTo(RobotExterns.IN_DOCKING);
        TrafficControlTest.Model model = new TrafficControlTest.Model();
        model.robot(1, 1, "stopped", 0, null, null); // area 0 in the test's model: the corridor
        externs.bindDevices(model);
        assertThat(externs.getPosition(1)).isEqualTo(2.0);
        externs.unbindDevices(new TrafficControlTest.Model());
        assertThat(externs.getPosition(1)).as("another model went: this one stays").isEqualTo(2.0);
        externs.unbindDevices(model);
        assertThat(externs.getPosition(1)).isEqualTo(RobotExterns.IN_DOCKING);
    }
}
