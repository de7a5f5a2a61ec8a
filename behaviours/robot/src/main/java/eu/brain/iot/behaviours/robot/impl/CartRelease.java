package eu.brain.iot.behaviours.robot.impl;

/**
 * When a robot without an errand may claim a cart, and which: how the fleet is released towards the doors.
 * <ul>
 * <li>{@link #waves(int) Waves} (robot-sim plans each go-to, the orchestrator resolves meetings): at most a wave of
 * robots go for carts at once, and none sets off while a robot of the wave still carries its cart, so the door is
 * crossed one way at a time; each robot claims the nearest cart.</li>
 * <li>{@link #continuous(int) Continuous} (the traffic planner drives): a robot claims a cart as soon as it is back
 * at its dock, whoever carries what, while fewer than a number of robots per door go for carts; the planner's
 * passage claims take each door one way at a time. Through a single door, each robot claims the <em>farthest</em>
 * cart, so the warehouse ends with short errands rather than a few long ones crossing an idle door; with several
 * doors, the nearest (the farthest was across the warehouse, through another door: 120x40, 60 robots, 3 doors,
 * seeds 11 and 12, 34-36% of the bound instead of 58-63%).</li>
 * </ul>
 * Why (60x30, 30 robots, 1 door, seeds 11 and 12, speed 5): with waves as large as the fleet, the whole fleet went
 * down, came back up, and robots docked late crossed an idle door alone: 58-61% of the bound. Released
 * continuously: 64-78%, nearest carts first, every robot at once, the robots waiting behind others 3-4% of the
 * time; 75-76% with at most 10 robots per door going for carts and farthest carts first, waiting 1.2-1.5%.
 * <p>
 * Immutable: any thread.
 */
final class CartRelease {
    /** Robots per door that may go for carts at once when released continuously. */
    static final int ROBOTS_PER_DOOR = 10;

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

    /** @param robotsPerDoor robots per door that may go for carts at once (at least 1) */
    static CartRelease continuous(int robotsPerDoor) {
        return new CartRelease(robotsPerDoor, true);
    }

    /**
     * @param goingForCarts robots on their way to a cart now
     * @param anyCarrying   whether some robot carries a cart to storage now
     * @param doors         the warehouse's doors (at least one counts)
     * @return whether a robot without an errand may claim a cart now
     */
    boolean open(long goingForCarts, boolean anyCarrying, int doors) {
        if (!perDoor) {
            return !anyCarrying && goingForCarts < robots;
        }
        return goingForCarts < (long) robots * Math.max(1, doors);
    }

    /**
     * @param doors the warehouse's doors
     * @return whether a robot claims the farthest waiting cart (else the nearest)
     */
    boolean farthestFirst(int doors) {
        return perDoor && doors == 1;
    }

    @Override
    public String toString() {
        return perDoor ? "released continuously, " + robots + " robots per door" : "waves of " + robots + " robots";
    }
}
