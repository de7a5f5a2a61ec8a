package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * Which waiting cart a robot goes for when the fleet, not the doors, bounds the warehouse (several doors): the
 * waiting carts are scheduled over the robots so that the last errand ends soonest, and a robot takes the longest
 * errand the schedule gives it; given none, it stays docked, because a robot back sooner does that cart in less time.
 * Going for the nearest cart, the robots docked far from the busiest door run out of carts behind their own door and
 * cross the warehouse for the last ones: a tail of long errands with most of the fleet docked (120x40, 60 robots,
 * 3 doors: the last quarter of a run had 91% of the robots docked).
 * <p>
 * The schedule is over estimates in steps: a robot's errand for a cart is the way from its dock to the cart and back
 * (storage lies on the way home), plus lifting and placing; a robot on an errand is free once it is back at its
 * dock. Carts are first given one at a time, each round the errand that can end first to the robot that ends it
 * (min-min), then carts move from the robot that ends last to the one that ends soonest while that ends the schedule
 * sooner. What the robot does first of its carts is the longest errand, so that the warehouse ends with short ones.
 * Estimates leave out the waits at the doors and between legs, which stretch every errand alike.
 * <p>
 * Not thread-safe: owned by the errand table's owner, the robot fleet's thread. Keeps the distances from each dock
 * for the map it was last asked about.
 */
final class CartSchedule {

    /** Steps a robot spends lifting a cart and putting it down (robot-sim's defaults: 2 each). */
    static final int HANDLING_STEPS = 4;

    /** Moves of a cart between robots tried after the first schedule, at most. */
    private static final int MAX_MOVES = 500;

    /** A robot the schedule may give carts: its dock, and how many steps until it is back there, free. */
    record Worker(String robot, Cell dock, int freeInSteps) {
    }

    private Grid grid;
    private final Map<Cell, Map<Cell, Integer>> fromDock = new HashMap<>();

    /**
     * @return the steps from the dock to the cell over the floor (walls and doors only), or {@code -1} when it
     *         cannot be reached
     */
    int steps(Grid map, Cell dock, Cell cell) {
        if (map != grid) {
            grid = map;
            fromDock.clear();
        }
        Integer d = fromDock.computeIfAbsent(dock, k -> map.distances(k, Set.of())).get(cell);
        return d == null ? -1 : d;
    }

    /** @return the estimated steps of an errand for the cart from the dock and back, or -1 when it cannot be done */
    int errand(Grid map, Cell dock, Cell cart) {
        int d = steps(map, dock, cart);
        return d < 0 ? -1 : 2 * d + HANDLING_STEPS;
    }

    /**
     * @param waiting carts on the floor outside storage that no robot claimed
     * @param workers the robots that may do them, the one asking among them
     * @return per robot, the carts the schedule gives it, the longest errand first
     */
    Map<String, List<CartState>> plan(Grid map, List<CartState> waiting, List<Worker> workers) {
        int w = workers.size();
        int c = waiting.size();
        int[][] cost = new int[w][c];
        for (int i = 0; i < w; i++) {
            for (int j = 0; j < c; j++) {
                cost[i][j] = errand(map, workers.get(i).dock(), waiting.get(j).cell());
            }
        }
        long[] load = new long[w];
        for (int i = 0; i < w; i++) {
            load[i] = Math.max(0, workers.get(i).freeInSteps());
        }
        int[] by = new int[c];
        Arrays.fill(by, -1);
        for (int round = 0; round < c; round++) { // min-min: the errand that can end first, to the robot ending it
            int bestCart = -1;
            int bestWorker = -1;
            long earliest = Long.MAX_VALUE;
            for (int j = 0; j < c; j++) {
                for (int i = 0; by[j] < 0 && i < w; i++) {
                    if (cost[i][j] >= 0 && load[i] + cost[i][j] < earliest) {
                        earliest = load[i] + cost[i][j];
                        bestCart = j;
                        bestWorker = i;
                    }
                }
            }
            if (bestCart < 0) {
                break; // no robot reaches the carts left
            }
            by[bestCart] = bestWorker;
            load[bestWorker] = earliest;
        }
        for (int move = 0; move < MAX_MOVES && moveOffTheLast(cost, load, by); move++) {
            // each move ends the schedule sooner
        }
        Map<String, List<CartState>> plan = new HashMap<>();
        for (int j = 0; j < c; j++) {
            if (by[j] >= 0) {
                plan.computeIfAbsent(workers.get(by[j]).robot(), k -> new ArrayList<>()).add(waiting.get(j));
            }
        }
        for (Map.Entry<String, List<CartState>> e : plan.entrySet()) {
            Cell dock = workers.stream().filter(x -> x.robot().equals(e.getKey())).findFirst().orElseThrow().dock();
            e.getValue().sort((a, b) -> Integer.compare(errand(map, dock, b.cell()), errand(map, dock, a.cell())));
        }
        return plan;
    }

    /**
     * Moves one cart from the robot whose errands end last to the robot that then ends soonest, when that ends the
     * schedule sooner.
     *
     * @return whether a cart moved
     */
    private static boolean moveOffTheLast(int[][] cost, long[] load, int[] by) {
        int last = 0;
        for (int i = 1; i < load.length; i++) {
            if (load[i] > load[last]) {
                last = i;
            }
        }
        int cart = -1;
        int to = -1;
        long best = load[last];
        for (int j = 0; j < by.length; j++) {
            if (by[j] != last) {
                continue;
            }
            for (int i = 0; i < load.length; i++) {
                long after = Math.max(load[last] - cost[last][j], load[i] + cost[i][j]);
                if (i != last && cost[i][j] >= 0 && after < best) {
                    best = after;
                    cart = j;
                    to = i;
                }
            }
        }
        if (cart < 0) {
            return false;
        }
        load[last] -= cost[last][cart];
        load[to] += cost[to][cart];
        by[cart] = to;
        return true;
    }

    /**
     * @return the cart the robot goes for now: the longest errand of those the schedule gives it, or empty when it
     *         gives it none
     */
    Optional<CartState> choose(String robot, Grid map, List<CartState> waiting, List<Worker> workers) {
        List<CartState> mine = plan(map, waiting, workers).get(robot);
        return mine == null || mine.isEmpty() ? Optional.empty() : Optional.of(mine.get(0));
    }
}
