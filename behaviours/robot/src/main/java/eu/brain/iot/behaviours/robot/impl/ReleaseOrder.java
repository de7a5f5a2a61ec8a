package eu.brain.iot.behaviours.robot.impl;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.function.LongSupplier;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * Which of the robots waiting for a cart goes first when fewer may go than wait ({@link CartRelease} says how many
 * may go now).
 * <ul>
 * <li>{@link #nearestDoorFirst Nearest a door first} (released continuously, the traffic planner drives): the robots
 * waiting nearest a doorway, by steps through the map, go first; ties go by name. A fleet larger than its doors can
 * keep busy then works from the docks nearest the doors, and the others stay parked instead of crossing the docking
 * rows and the storage area to reach the same doors (120x40, 3 doors: BENCHMARKS.md, "With the traffic planner",
 * the fleet-size curve).</li>
 * <li>{@link #asAsked As asked} (released in waves, the paper's warehouse): whichever robot asks while the wave is
 * open goes.</li>
 * </ul>
 * A robot waits from its first ask (its model starting an errand with carts left, or a robot without an errand going
 * on) until it claims a cart. One that has not asked again within {@code freshNanos} (its carts used up, out of
 * reach, or on its way) no longer counts, so a robot that will never go holds nobody back. Docks do not move: the
 * steps from each cell to its nearest doorway are computed once per map.
 * <p>
 * Not thread-safe: owned by the robot fleet's thread ({@link RobotFleet}).
 */
final class ReleaseOrder {

    private final boolean nearestFirst;
    private final long freshNanos;
    private final LongSupplier clock;
    /** The robots waiting for a cart, each with the steps from where it waits to a doorway and its last ask. */
    private final Map<String, Waiting> waiting = new HashMap<>();
    private final Map<Cell, Integer> doorSteps = new HashMap<>();
    private Grid stepsOf;

    private record Waiting(int steps, long askedNanos) {
    }

    private ReleaseOrder(boolean nearestFirst, long freshNanos, LongSupplier clock) {
        this.nearestFirst = nearestFirst;
        this.freshNanos = freshNanos;
        this.clock = clock;
    }

    /**
     * @param freshNanos how long a robot's ask counts (a few polls of the binding, which asks again at each)
     * @param clock      the time in nanoseconds ({@link System#nanoTime} outside tests)
     */
    static ReleaseOrder nearestDoorFirst(long freshNanos, LongSupplier clock) {
        return new ReleaseOrder(true, freshNanos, clock);
    }

    static ReleaseOrder asAsked() {
        return new ReleaseOrder(false, 0, System::nanoTime);
    }

    /**
     * @param robot the robot that asks
     * @param at    where it waits
     * @param free  how many robots may still go for carts now
     * @return whether this robot may go now: fewer than {@code free} robots that wait are ahead of it
     */
    boolean mayGo(String robot, Cell at, long free, Grid grid) {
        if (!nearestFirst || free <= 0) {
            return free > 0;
        }
        long now = clock.getAsLong();
        Waiting mine = new Waiting(steps(at, grid), now);
        waiting.put(robot, mine);
        waiting.values().removeIf(w -> now - w.askedNanos() > freshNanos);
        long ahead = waiting.entrySet().stream().filter(o -> !o.getKey().equals(robot)
                && (o.getValue().steps() < mine.steps()
                        || o.getValue().steps() == mine.steps() && o.getKey().compareTo(robot) < 0))
                .count();
        return ahead < free;
    }

    /** The robot claimed a cart: it no longer waits. */
    void went(String robot) {
        waiting.remove(robot);
    }

    /** @return the steps from the cell to the nearest doorway, {@link Integer#MAX_VALUE} when none can be reached */
    private int steps(Cell at, Grid grid) {
        if (grid != stepsOf) {
            doorSteps.clear();
            stepsOf = grid;
        }
        return doorSteps.computeIfAbsent(at, c -> {
            if (grid.area(c) == Grid.DOORWAY) {
                return 0;
            }
            Cell door = grid.nearest(c, n -> grid.area(n) == Grid.DOORWAY, Set.of());
            return door == null ? Integer.MAX_VALUE : grid.steps(c, door, Set.of());
        });
    }

    @Override
    public String toString() {
        return nearestFirst ? "the robots nearest a door first" : "as the robots ask";
    }
}
