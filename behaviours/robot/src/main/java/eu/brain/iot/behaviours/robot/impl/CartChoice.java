package eu.brain.iot.behaviours.robot.impl;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * Which waiting cart a robot without an errand goes for, by path (not as the crow flies) from where it stands, in
 * the order {@link CartRelease#order} gives:
 * <ul>
 * <li>{@link Order#NEAREST}: the nearest;</li>
 * <li>{@link Order#FARTHEST}: the farthest, through a single door: the warehouse then ends with short errands rather
 * than a few long ones crossing an idle door;</li>
 * <li>{@link Order#DEEPEST_BEHIND_NEAREST_DOOR}: with several doors, of the carts behind the door the robot reaches
 * first (the carts nearest that door of all doors), the one deepest in the unload area; when that door has none
 * left, the next door's. The long errands go first, as through one door, and no robot crosses the warehouse to
 * another door while its own has carts (the farthest by path lay behind another door: 120x40, 60 robots, 3 doors,
 * 34-36% of the bound against 58-63% for the nearest).</li>
 * </ul>
 * Ties go to the first cart in the order given (the device model's, sorted by id), so the choice is the same for the
 * same fleet.
 * <p>
 * Stateless: the errand table gives the carts no robot claimed. Any thread.
 */
final class CartChoice {

    /** Which of the waiting carts is taken first. */
    enum Order { NEAREST, FARTHEST, DEEPEST_BEHIND_NEAREST_DOOR }

    private CartChoice() {
    }

    /**
     * @param from       where the robot stands
     * @param candidates carts on the floor outside storage that no robot claimed
     * @return the cart, or empty when none is left (or none can be reached)
     */
    static Optional<CartState> choose(Cell from, List<CartState> candidates, Grid grid, Order order) {
        Map<Cell, Integer> reach = grid.distances(from, Set.of()); // one search for every cart
        Map<Cell, Integer> depth = order == Order.DEEPEST_BEHIND_NEAREST_DOOR
                ? grid.distances(grid.cells(Grid.DOORWAY), Set.of()) : Map.of();
        long cells = (long) grid.width() * grid.height();
        CartState best = null;
        long bestKey = Long.MAX_VALUE;
        for (CartState c : candidates) {
            Integer steps = reach.get(c.cell());
            if (steps == null) {
                continue; // walled in: no robot reaches it
            }
            long key = switch (order) {
                case NEAREST -> steps;
                case FARTHEST -> -steps;
                // the way to the cart's door first (the steps beyond its door are its depth), then the deepest
                case DEEPEST_BEHIND_NEAREST_DOOR -> {
                    int d = depth.getOrDefault(c.cell(), 0);
                    yield (steps - d) * cells - d;
                }
            };
            if (key < bestKey) {
                best = c;
                bestKey = key;
            }
        }
        return Optional.ofNullable(best);
    }
}
