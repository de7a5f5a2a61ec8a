package eu.brain.iot.behaviours.robot.impl;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * Which waiting cart a robot without an errand goes for: the nearest by path from where it stands, or the farthest
 * when the robots are released continuously through a single door ({@link CartRelease#farthestFirst}): the
 * warehouse then ends with short errands rather than a few long ones crossing an idle door. Ties go to the first
 * cart in the order given (the device model's, sorted by id), so the choice is the same for the same fleet.
 * <p>
 * Stateless: the errand table gives the carts no robot claimed. Any thread.
 */
final class CartChoice {

    /** Which end of the waiting carts, by path from the robot, is taken first. */
    enum Order { NEAREST, FARTHEST }

    private CartChoice() {
    }

    /**
     * @param from       where the robot stands
     * @param candidates carts on the floor outside storage that no robot claimed
     * @return the cart, or empty when none is left
     */
    static Optional<CartState> choose(Cell from, List<CartState> candidates, Grid grid, Order order) {
        Map<Cell, Integer> reach = grid.distances(from, Set.of()); // one search for every cart
        CartState best = null;
        int bestSteps = Integer.MAX_VALUE;
        for (CartState c : candidates) {
            int steps = reach.getOrDefault(c.cell(), Integer.MAX_VALUE);
            if (steps == Integer.MAX_VALUE) {
                continue; // walled in: no robot reaches it
            }
            if (order == Order.FARTHEST) {
                steps = -steps;
            }
            if (steps < bestSteps) {
                best = c;
                bestSteps = steps;
            }
        }
        return Optional.ofNullable(best);
    }
}
