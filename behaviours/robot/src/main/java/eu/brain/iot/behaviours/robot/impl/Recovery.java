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
 * sent, the end of a leg): it goes on ({@link Fix#GO_ON}; a go-to is never sent twice);</li>
 * <li>going home carrying a cart (its place was refused once too often, or failed, or went with a node that died):
 * it carries the cart to storage again ({@link Fix#CARRY_BACK}).</li>
 * </ul>
 * These hold in the model's UNLOAD place; going home, in STORAGE, the last two, in DOCKING going on home (the model
 * stays there only once it has lifted all its carts). Stateless: any thread.
 */
final class Recovery {

    /** What brings the robot back onto its errand. */
    enum Fix {
        /** Report the cart in front of it ({@code fromUnloadObstacle}, inFrontOfCart): the model lifts it again. */
        THROUGH_CART,
        /** Go on with the errand ({@link RobotFleet#resume}), for the reason given. */
        GO_ON,
        /**
         * Carry the cart to storage again ({@link Errands#carryBack}): the model, past STORAGE already, goes through
         * CART as for {@link #THROUGH_CART}, and puts the cart down again at its new storage cell.
         */
        CARRY_BACK
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
     * @param placeUnseen   whether a place sent to the robot has not shown in the device model yet
     *                      ({@link RobotFleet#placeUnseen}; asked only for a robot going home carrying a cart)
     * @return the fix, or empty when the robot is on its errand (the normal moves apply)
     */
    static Optional<Step> inUnload(RobotState s, Errands.Errand e, boolean modelCarrying, BooleanSupplier cartOnFloor,
            BooleanSupplier workLeft, BooleanSupplier placeUnseen) {
        Optional<Step> back = carryingHome(s, e, placeUnseen);
        if (back.isPresent()) {
            return back;
        }
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

    /**
     * @return carrying the cart back, for a robot going home that stands idle with a cart and no place sent to it
     *         still to show: the place went with a refusal, a failed mission or a node that died
     */
    static Optional<Step> carryingHome(RobotState s, Errands.Errand e, BooleanSupplier placeUnseen) {
        if (e.leg() == Errands.Leg.TO_DOCK && s.idle() && s.carrying() && !placeUnseen.getAsBoolean()) {
            return Optional.of(new Step(Fix.CARRY_BACK, "going home carrying " + s.cart()));
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
