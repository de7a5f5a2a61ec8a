package eu.brain.iot.behaviours.robot.impl;

import java.util.List;
import java.util.Optional;

import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotNames;
import eu.brain.iot.behaviours.warehouse.RobotState;

/**
 * When a robot without an errand may claim a cart, and which: how the fleet is released towards the doors.
 * <ul>
 * <li>{@link #waves(int) Waves} (robot-sim plans each go-to, the orchestrator resolves meetings): at most a wave of
 * robots go for carts at once, and none sets off while a robot of the wave still carries its cart, so the door is
 * crossed one way at a time; each robot claims the nearest cart.</li>
 * <li>{@link #continuous(int) Continuous} (the traffic planner drives): a robot claims a cart as soon as it is back
 * at its dock, while fewer than a number of robots per door are out on an errand for a cart (going for one or
 * carrying it); the planner's passage claims and door batches take each door one way at a time.
 * Each robot claims the cart with the longest errand behind its door first ({@link #order}), so the warehouse ends
 * with short errands rather than a few long ones.</li>
 * </ul>
 * Released in waves, a robot carrying its cart back through the door also waits until every robot of the wave going
 * for a cart is down ({@link #mayCarryBack}), so that the door is crossed one way at a time. Released continuously,
 * robots go as soon as they are back: a wave as large as the fleet leaves robots that docked late crossing an idle
 * door alone, and more robots per door than the door can pass only queue behind it (BENCHMARKS.md, "With the
 * traffic planner", has the figures of each choice).
 * <p>
 * Immutable: any thread.
 */
final class CartRelease {
    /**
     * Robots per door that may be out on an errand for a cart at once (going for one or carrying it) when released
     * continuously: a fleet larger than the doors and aisles carry only crowds them, and the rest wait docked (60x30,
     * one door: 20 of 30 robots; 120x40, 3 doors: 60 whatever the fleet's size; BENCHMARKS.md, "With the traffic
     * planner").
     */
    static final int ROBOTS_PER_DOOR = 20;

    private final int robots;
    private final boolean perDoor;

    private CartRelease(int robots, boolean perDoor) {
        this.robots = Math.max(1, robots);
        this.perDoor = perDoor;
    }

    /** @param robots robots that may go for carts at once (at least 1) */
    static CartRelease waves(int robots) {
        return new CartRelease(robots, false);
    }

    /** @param robotsPerDoor robots per door that may be out on an errand for a cart at once (at least 1) */
    static CartRelease continuous(int robotsPerDoor) {
        return new CartRelease(robotsPerDoor, true);
    }

    /**
     * @param goingForCarts robots on their way to a cart now
     * @param carrying      robots carrying a cart to storage now
     * @param doors         the warehouse's doors (at least one counts)
     * @return whether a robot without an errand may claim a cart now
     */
    boolean open(long goingForCarts, long carrying, int doors) {
        if (!perDoor) {
            return carrying == 0 && goingForCarts < robots;
        }
        return goingForCarts + carrying < robotsOut(doors);
    }

    /**
     * @param doors the warehouse's doors
     * @return the most robots out on errands for carts at once: a wave's robots, or the robots per door times the
     *         doors (at least one counts)
     */
    long robotsOut(int doors) {
        return perDoor ? (long) robots * Math.max(1, doors) : robots;
    }

    /**
     * @param doors the warehouse's doors
     * @return which waiting cart a robot claims first ({@link CartChoice}): released continuously, the farthest
     *         through a single door and the deepest behind its nearest door through several; in waves, the nearest
     */
    CartChoice.Order order(int doors) {
        if (!perDoor) {
            return CartChoice.Order.NEAREST;
        }
        return doors <= 1 ? CartChoice.Order.FARTHEST : CartChoice.Order.DEEPEST_BEHIND_NEAREST_DOOR;
    }

    /**
     * Whether a robot carrying a cart back through the door may set off: released continuously, at once (the
     * planner's reservations take the door one way at a time); in waves, once every robot of the wave going for a
     * cart is down (in the unload area, at its cart, or stopped behind a carrier, which must move first), in a fleet
     * larger than one group (three robots): in the paper's warehouse the orchestrator resolves the meetings at the
     * door (Listing 7); in a larger fleet one robot still coming down met the wave's carriers queued at the door, and
     * they all waited longer than REQ-2 allows for its side step. A robot the edge cannot reach is not waited for.
     *
     * @param robot         the carrier
     * @param goingForCarts the errands of the robots going for carts
     * @param robots        every robot now
     */
    boolean mayCarryBack(String robot, List<Errands.Errand> goingForCarts, List<RobotState> robots) {
        if (perDoor || robots.size() <= RobotNames.PER_GROUP) {
            return true;
        }
        for (Errands.Errand e : goingForCarts) {
            if (e.robot().equals(robot)) {
                continue;
            }
            Optional<RobotState> s = robots.stream().filter(r -> r.id().equals(e.robot())).findFirst();
            if (s.isPresent() && s.get().reachable() && s.get().area() != Grid.UNLOAD
                    && !s.get().cell().equals(e.cartCell()) && !behindACarrier(s.get(), robots)) {
                return false;
            }
        }
        return true;
    }

    /** A robot stopped behind one carrying a cart does not hold the carriers back: the one in its way must move. */
    private static boolean behindACarrier(RobotState s, List<RobotState> robots) {
        return s.facesRobot() && robots.stream().anyMatch(o -> o.cell().equals(s.ahead()) && o.carrying());
    }

    @Override
    public String toString() {
        return perDoor ? "released continuously, " + robots + " robots per door" : "waves of " + robots + " robots";
    }
}
