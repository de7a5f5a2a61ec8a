package eu.brain.iot.behaviours.robot.impl;

import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * Which storage cell a robot that lifted a cart carries it to: a free storage cell that a robot carrying a cart can
 * reach around the other carts, whose cart cuts no free storage cell, nor a cell another robot is carrying a cart
 * to, off from where the carts come from (robots carrying carts cannot drive under others, so storage filled in the
 * wrong order walls its own cells in: in the 60x30 warehouse, with 57 of 60 carts put down, the last three robots
 * found no free storage cell they could reach), and that makes the rest of its trip shortest: the path there plus
 * the distance from it to the robot's dock (a storage cell on the way home keeps the robots' ways home short and
 * apart, instead of every robot crossing the docking rows to its dock).
 * <p>
 * Stateless: the errand table gives the cells already given to carts. Any thread.
 */
final class StorageChoice {

    private StorageChoice() {
    }

    /**
     * @param from     where the robot stands, under the cart it lifted
     * @param dock     the robot's dock, or {@code null} when not known
     * @param walls    cells a carrying robot cannot enter: carts on the floor and storage cells given to other carts
     * @param inFlight storage cells other robots are carrying their carts to
     * @return the cell, or {@code null} when no free storage cell can be reached with a cart
     */
    static Cell choose(Grid grid, Cell from, Cell dock, Set<Cell> walls, List<Cell> inFlight) {
        Map<Cell, Integer> steps = grid.distances(from, walls);
        List<Cell> free = grid.cells(Grid.STORAGE).stream().filter(steps::containsKey).toList();
        List<Cell> byTrip = free.stream().sorted(Comparator.comparingInt(
                (Cell c) -> steps.get(c) + (dock == null ? 0 : c.distance(dock)))).toList();
        for (Cell c : byTrip) {
            if (keepsStorageOpen(grid, from, c, walls, free, inFlight)) {
                return c;
            }
        }
        return null;
    }

    /**
     * A cart put down at {@code c} must not cut any free storage cell, nor a cell another robot is carrying its cart
     * to, off from where the carts come from.
     */
    private static boolean keepsStorageOpen(Grid grid, Cell from, Cell c, Set<Cell> walls, List<Cell> free,
            List<Cell> inFlight) {
        Set<Cell> blocked = new HashSet<>(walls);
        blocked.add(c);
        Map<Cell, Integer> after = grid.distances(from, blocked);
        for (Cell f : free) {
            if (!f.equals(c) && !after.containsKey(f)) {
                return false;
            }
        }
        for (Cell d : inFlight) { // reached when a neighbour is: the cell itself is the end of that robot's path
            if (grid.neighbours(d).stream().noneMatch(after::containsKey)) {
                return false;
            }
        }
        return true;
    }
}
