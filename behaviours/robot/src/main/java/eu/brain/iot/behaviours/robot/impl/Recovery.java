package eu.brain.iot.behaviours.robot.impl;

import java.util.Optional;
import java.util.function.BooleanSupplier;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.RobotState;

/**
 * The robot binding's recovery step: a robot whose device and errand disagree is brought back onto its errand, before
 * any normal move of the binding's rules is looked at ({@link RobotBinding}). The cases:
 * <ul>
 * <li>taken over carrying a cart (the behaviour started again, so the model's {@code carrying} is false): the model
 * goes through CART, where {@code liftCart} finds the cart lifted already, to carry it on
 * ({@link Fix#THROUGH_CART});</li>
 * <li>its errand says it carries a cart that stands on the floor (put down just before a take-over, or its pick
 * failed): it goes on without it ({@link Fix#GO_ON}: in storage the cart counts as placed, elsewhere it goes back to
 * the table);</li>
 * <li>carrying a cart without a storage cell yet: it asks again ({@link Fix#GO_ON});</li>
 * <li>idle before its errand's goal, or without an errand while a cart waits (a go-to cancelled, lost, refused or never
 * sent, the end of a leg): it goes on ({@link Fix#GO_ON}; a go-to is never sent twice).</li>
 * </ul>
 * These hold in the model's UNLOAD place; going home (STORAGE, DOCKING) only the last applies. Stateless: any thread.
 */
final class Recovery {

    /** What brings the robot back onto its errand. */
    enum Fix {
        /** Report the cart in front of it ({@code fromUnloadObstacle}, inFrontOfCart): the model lifts it again. */
        THROUGH_CART,
        /** Go on with the errand ({@link RobotFleet#resume}), for the reason given. */
        GO_ON
    }

    /** A fix and why (the reason goes to {@link RobotFleet#resume} and its log). */
    record Step(Fix fix, String why) {
    }

    private Recovery() {
    }

    /**
     * @param s             the robot now
     * @param e             its errand
     * @param modelCarrying the model's {@code carrying}
     * @param cartOnFloor   whether the cart its errand says it carries stands on the floor, put down by it
     *                      ({@link RobotFleet#cartPutDown}; asked only when the errand carries one)
     * @param workLeft      whether a cart on the floor waits for a robot (asked only for a robot without a goal)
     * @return the fix, or empty when the robot is on its errand (the normal moves apply)
     */
    static Optional<Step> inUnload(RobotState s, Errands.Errand e, boolean modelCarrying, BooleanSupplier cartOnFloor,
            BooleanSupplier workLeft) {
        boolean fetching = e.leg() == Errands.Leg.TO_STORAGE || e.leg() == Errands.Leg.TO_CART;
        if (fetching && s.carrying() && !modelCarrying) {
            return Optional.of(new Step(Fix.THROUGH_CART, "taken over carrying its cart"));
        }
        if (e.leg() == Errands.Leg.TO_STORAGE && cartOnFloor.getAsBoolean()) {
            return Optional.of(new Step(Fix.GO_ON, "carrying nothing"));
        }
        if (e.leg() == Errands.Leg.TO_STORAGE && e.drop() == null && s.idle()) {
            return Optional.of(new Step(Fix.GO_ON, "looking for a free storage cell"));
        }
        return idleBeforeItsGoal(s, e, workLeft);
    }

    /**
     * @return going on, for a robot idle before its errand's goal, or without one while a cart waits
     */
    static Optional<Step> idleBeforeItsGoal(RobotState s, Errands.Errand e, BooleanSupplier workLeft) {
        Cell goal = e.goal();
        if (s.idle() && (goal != null ? !s.cell().equals(goal) : workLeft.getAsBoolean())) {
            return Optional.of(new Step(Fix.GO_ON, "idle before its goal"));
        }
        return Optional.empty();
    }

    /** @return going on, for a robot going home that stands idle and empty elsewhere than its dock */
    static Optional<Step> homeward(RobotState s, Errands.Errand e) {
        if (e.leg() == Errands.Leg.TO_DOCK && s.idle() && !s.carrying() && !s.cell().equals(e.dock())) {
            return Optional.of(new Step(Fix.GO_ON, "idle before its dock"));
        }
        return Optional.empty();
    }
}
