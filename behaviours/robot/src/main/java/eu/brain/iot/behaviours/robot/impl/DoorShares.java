package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * Through several doors, behind which doors a robot about to claim a cart may take it: each door gets a share of the
 * robots out on errands for carts in proportion to its carts not yet placed, so that the doors run out of carts
 * together. Carts fall unevenly behind the doors, and with every robot working the door nearest its dock, the door
 * with the most carts keeps its robots for one errand more after the others have finished (BENCHMARKS.md, "With the
 * traffic planner").
 * <p>
 * A cart is behind the doorway nearest it by path. A door's carts not yet placed are its unclaimed carts and those of
 * robots going for or carrying one of its carts; its share of the robots out is that fraction of {@code robotsOut}
 * (the most that may be out at once). A door is open while it has unclaimed carts and fewer robots than its share;
 * when no door is, every door with unclaimed carts is. Among the open doors the robot takes the one it reaches first
 * ({@link CartChoice}), so robots spill over to the next door only where a door has its share, and cross no further
 * than they must.
 * <p>
 * Not thread-safe: owned by the robot fleet's thread, like the {@link Errands} table that holds it. It keeps, per map,
 * the steps from each doorway to every cell (the map's walls only: carts on the floor do not move a cart's door),
 * which {@link EndGame} reads too.
 */
final class DoorShares {

    private Grid grid;
    private List<Cell> doorways = List.of();
    private final List<Map<Cell, Integer>> fromDoorway = new ArrayList<>();
    private final Map<Cell, Cell> doorOf = new HashMap<>();

    /**
     * @param candidates the carts a robot may claim now (unclaimed, on the floor outside storage)
     * @param outCarts   the cells the carts of the robots out on errands for carts were lifted from (going for one:
     *                   where it stands), one per robot
     * @param robotsOut  the most robots that may be out on errands for carts at once
     * @return the candidates behind the doors open to the next claim; all of them with fewer than two doors
     */
    List<CartState> behindOpenDoors(List<CartState> candidates, List<Cell> outCarts, int robotsOut, Grid map) {
        load(map);
        if (doorways.size() < 2 || candidates.isEmpty()) {
            return candidates;
        }
        Map<Cell, Integer> unclaimed = new HashMap<>();
        Map<Cell, Integer> out = new HashMap<>();
        candidates.forEach(c -> unclaimed.merge(door(c.cell()), 1, Integer::sum));
        outCarts.forEach(c -> out.merge(door(c), 1, Integer::sum));
        int notPlaced = candidates.size() + outCarts.size();
        List<CartState> open = new ArrayList<>();
        for (CartState c : candidates) {
            Cell door = door(c.cell());
            int behind = unclaimed.get(door) + out.getOrDefault(door, 0);
            double share = (double) robotsOut * behind / notPlaced;
            if (out.getOrDefault(door, 0) < share) {
                open.add(c);
            }
        }
        return open.isEmpty() ? candidates : open;
    }

    /**
     * @return the doorway nearest the cell by path (the first of the map's doorways on a tie); null if none reaches it
     *         or the map has fewer than two doorways
     */
    Cell doorOf(Cell cell, Grid map) {
        load(map);
        return doorways.size() < 2 ? null : door(cell);
    }

    /**
     * @return the steps from the doorway nearest the cell by path (the only one, through one door) to every cell the
     *         map's walls let it reach; empty when the map has no doorway or none reaches the cell
     */
    Map<Cell, Integer> stepsFromDoorOf(Cell cell, Grid map) {
        load(map);
        Cell door = door(cell);
        return door == null ? Map.of() : fromDoorway.get(doorways.indexOf(door));
    }

    private Cell door(Cell cell) {
        return doorOf.computeIfAbsent(cell, c -> {
            Cell best = null;
            int bestSteps = Integer.MAX_VALUE;
            for (int i = 0; i < doorways.size(); i++) {
                Integer steps = fromDoorway.get(i).get(c);
                if (steps != null && steps < bestSteps) {
                    best = doorways.get(i);
                    bestSteps = steps;
                }
            }
            return best;
        });
    }

    private void load(Grid map) {
        if (map == grid) {
            return;
        }
        grid = map;
        doorways = map.cells(Grid.DOORWAY);
        fromDoorway.clear();
        doorOf.clear();
        doorways.forEach(d -> fromDoorway.add(map.distances(d, Set.of())));
    }
}
