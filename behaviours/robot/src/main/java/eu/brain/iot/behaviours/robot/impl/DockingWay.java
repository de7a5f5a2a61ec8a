package eu.brain.iot.behaviours.robot.impl;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * The way in and out of the docking area, and the dock of a robot first met out on the floor (behaviours/README.md,
 * "Errands"). robot-sim plans the shortest path, robots ignored: without legs of their own, robots ran along the
 * docking rows past robots parked at their docks, which the orchestrator then sent aside one after the other (the
 * 60x30 warehouse's longest waits). So a robot going home is sent first to the floor cell where its dock meets the
 * floor ({@link #edgeOfDocking}), then into the docking area leg by straight leg ({@link #straightToward}), through no
 * other robot's dock; a robot leaving goes out leg by straight leg to the floor cell nearest to it.
 * <p>
 * Stateless: the other robots' docks and parked cells are given by the caller (the errand table). Any thread.
 */
final class DockingWay {

    private DockingWay() {
    }

    /**
     * The next go-to of a robot whose goal is {@code goal}: in or next to the docking area, the first straight leg
     * of its way in or out; any other goal as it is (on the floor robot-sim plans).
     *
     * @param at     where the robot stands
     * @param dock   its dock ({@code null} when not known yet)
     * @param others other robots' docks and the cells where other robots stand parked in the docking area
     */
    static Cell next(Cell at, Cell goal, Cell dock, Grid grid, Set<Cell> others) {
        if (!concerns(at, goal, dock, grid)) {
            return goal;
        }
        if (grid.area(at) != Grid.DOCKING) {
            Cell edge = edgeOfDocking(dock, grid, others);
            return edge != null && !edge.equals(at) ? edge : straightToward(at, goal, grid, others);
        }
        Cell target = grid.area(goal) == Grid.DOCKING ? goal : edgeOfDocking(at, grid, others);
        return target == null ? goal : straightToward(at, target, grid, others);
    }

    /**
     * @return whether the way from {@code at} to {@code goal} is this policy's: the robot stands in the docking area,
     *         or goes to its dock; else robot-sim plans it, and {@link #next} gives the goal as it is
     */
    static boolean concerns(Cell at, Cell goal, Cell dock, Grid grid) {
        return grid.area(at) == Grid.DOCKING || goal.equals(dock);
    }

    /**
     * Where a robot crosses the edge of the docking area nearest to {@code from}: the nearest cell outside the
     * docking area, reached through docking cells that are no other robot's dock.
     *
     * @param from   the robot's dock (going home) or its cell (leaving)
     * @param others other robots' docks and parked cells ({@code from} itself never counts)
     * @return the cell, or {@code null} when none exists
     */
    static Cell edgeOfDocking(Cell from, Grid grid, Set<Cell> others) {
        Set<Cell> blocked = without(others, from, null);
        return grid.nearest(from, c -> grid.area(c) != Grid.DOCKING, blocked);
    }

    /**
     * The first straight leg of the way from {@code from} to {@code to} through no other robot's dock: robot-sim
     * plans its own shortest path (A*, ties broken its way), which between two cells of one row or column is that
     * straight line and nothing else, so a go-to to the end of the first straight leg takes the robot exactly there.
     *
     * @return the end of the first straight leg, or {@code to} when there is no such way
     */
    static Cell straightToward(Cell from, Cell to, Grid grid, Set<Cell> others) {
        List<Cell> path = grid.path(from, to, without(others, from, to));
        if (path == null || path.isEmpty()) {
            return to;
        }
        Cell last = path.get(0);
        int dx = last.x() - from.x();
        int dy = last.y() - from.y();
        for (int i = 1; i < path.size(); i++) {
            Cell c = path.get(i);
            if (c.x() - last.x() != dx || c.y() - last.y() != dy) {
                break;
            }
            last = c;
        }
        return last;
    }

    /**
     * The dock of a robot first met out on the floor (or moving): {@code known}, the one an earlier run learnt for
     * it, unless another robot has it now; else the nearest docking cell not {@code taken}, first among those next to
     * no taken cell (robots parked side by side at the edge of the docking area would stand in each other's way in
     * and out), then among all.
     *
     * @param known    the dock an earlier run learnt, or {@code null}
     * @param docks    the docks of the robots seen so far
     * @param taken    those docks, the docks remembered for other robots and the cells other robots stand on
     * @return the dock, or {@code null} when the docking area has no free cell
     */
    static Cell dockFor(Cell from, Cell known, Set<Cell> docks, Set<Cell> taken, Grid grid) {
        if (known != null && !docks.contains(known)) {
            return known;
        }
        Cell spaced = grid.nearest(from, c -> grid.area(c) == Grid.DOCKING && !taken.contains(c)
                && grid.neighbours(c).stream().noneMatch(taken::contains), Set.of());
        return spaced != null ? spaced
                : grid.nearest(from, c -> grid.area(c) == Grid.DOCKING && !taken.contains(c), Set.of());
    }

    private static Set<Cell> without(Set<Cell> others, Cell a, Cell b) {
        if (!others.contains(a) && (b == null || !others.contains(b))) {
            return others;
        }
        Set<Cell> copy = new HashSet<>(others);
        copy.remove(a);
        if (b != null) {
            copy.remove(b);
        }
        return copy;
    }
}
