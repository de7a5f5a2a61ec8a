package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.robot.RobotBehavior;
import eu.brain.iot.behaviours.warehouse.CartBudget;

/** The budget a run checks before it starts is the one the generated robot model counts down. */
class CartBudgetTest {

    @Test
    void theRobotModelStartsWithTheBudgetTheRunChecks() {
        RobotBehavior robot = new RobotBehavior(new RobotExterns(), 1);
        assertThat(robot.data()).containsEntry("cart", CartBudget.PER_ROBOT);
    }

    @Test
    void robotsForRoundsUpAndCartsForMultiplies() {
        assertThat(CartBudget.robotsFor(30)).isEqualTo(10);
        assertThat(CartBudget.robotsFor(31)).isEqualTo(11);
        assertThat(CartBudget.robotsFor(0)).isZero();
        assertThat(CartBudget.cartsFor(10)).isEqualTo(30);
    }
}
