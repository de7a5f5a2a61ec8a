package eu.brain.iot.behaviours.robot.impl;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.RobotState;

/**
 * The robots the orchestrator told to step aside (without the traffic planner), and how long each keeps to its side
 * cell: it drives there, then waits while the robot it let pass (the one in front of it when it was told) is within
 * two cells and still on a mission, for a limited time. Only that robot is waited for: two robots sent aside near
 * each other would otherwise wait for each other for ever.
 * <p>
 * Not thread-safe: owned by the robot fleet's thread ({@link RobotFleet}).
 */
final class SideSteps {

    /** Cells within which the robot let pass still counts as coming by. */
    static final int PASSING_CELLS = 2;

    /** A robot stepping aside: to {@code cell}, for {@code passer} ({@code null}: none seen), since {@code atNanos}. */
    private record Aside(Cell cell, String passer, long atNanos) {
    }

    private final Map<String, Aside> aside = new HashMap<>();
    private final long maxNanos;

    /** @param maxNanos how long a robot waits aside at most (wall time) */
    SideSteps(long maxNanos) {
        this.maxNanos = maxNanos;
    }

    /** The robot is told to step aside to {@code cell}, letting {@code passer} (or nobody known) go by. */
    void told(String robot, Cell cell, String passer) {
        aside.put(robot, new Aside(cell, passer, System.nanoTime()));
    }

    /**
     * @param s      the robot now
     * @param robots each robot now, by id (where the robot it let pass is)
     * @return whether it keeps to its side step: still on its way there, or waiting there while the robot it let
     *         pass comes by; once not, the side step is forgotten
     */
    boolean holds(RobotState s, Function<String, Optional<RobotState>> robots) {
        Aside side = aside.get(s.id());
        if (side == null) {
            return false;
        }
        if (!s.cell().equals(side.cell()) && !s.idle()) {
            return true; // still on its way aside
        }
        if (s.cell().equals(side.cell()) && stillPassing(s, side, robots)) {
            return true;
        }
        aside.remove(s.id());
        return false;
    }

    private boolean stillPassing(RobotState s, Aside side, Function<String, Optional<RobotState>> robots) {
        if (System.nanoTime() - side.atNanos() > maxNanos || side.passer() == null) {
            return false;
        }
        return robots.apply(side.passer()).filter(p -> p.cell().distance(s.cell()) <= PASSING_CELLS && !p.idle())
                .isPresent();
    }
}
