package eu.brain.iot.behaviours.warehouse;

/**
 * How many carts the robot model lets one robot lift: Robot.bip's {@code data int cart = 3}, counted down by
 * {@code liftCart}; a robot whose count is 0 stays docked ({@code dockingToStart} needs {@code cart > 0}). So a
 * warehouse needs at least a third as many robots as carts, which a run checks before it starts. Stateless.
 */
public final class CartBudget {

    /** The carts one robot lifts at most (the robot model's initial {@code cart}). */
    public static final int PER_ROBOT = 3;

    private CartBudget() {
    }

    /** @return the fewest robots that can move {@code carts} carts */
    public static int robotsFor(int carts) {
        return (Math.max(0, carts) + PER_ROBOT - 1) / PER_ROBOT;
    }

    /** @return the most carts {@code robots} robots can move */
    public static int cartsFor(int robots) {
        return Math.max(0, robots) * PER_ROBOT;
    }
}
