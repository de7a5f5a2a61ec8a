package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;

/** Which waiting cart a robot goes for: nearest or farthest by path (not as the crow flies), none when none waits. */
class CartChoiceTest {

    /** A wall between the robot's column and the near-looking cart: by path, the cart at (1,5) is the nearest. */
    private static final Grid ROOM = Grid.parse(String.join("\n",
            "#######",
            "#d....#",
            "####..#",
            "#.....#",
            "#..####",
            "#.....#",
            "#######"));

    private static final CartState BEHIND_THE_WALL = new CartState("cart1", new Cell(1, 3), null);
    private static final CartState DOWN_THE_LANE = new CartState("cart2", new Cell(4, 1), null);
    private static final CartState FAR = new CartState("cart3", new Cell(5, 5), null);

    @Test
    void theNearestByPathOrTheFarthest() {
        List<CartState> carts = List.of(BEHIND_THE_WALL, DOWN_THE_LANE, FAR);
        Cell robot = new Cell(1, 1);
        assertThat(CartChoice.choose(robot, carts, ROOM, CartChoice.Order.NEAREST)).contains(DOWN_THE_LANE);
        assertThat(CartChoice.choose(robot, carts, ROOM, CartChoice.Order.FARTHEST)).contains(FAR);
        assertThat(CartChoice.choose(robot, List.of(BEHIND_THE_WALL, FAR), ROOM, CartChoice.Order.NEAREST))
                .as("(1,3) is two cells away as the crow flies, seven by path").contains(BEHIND_THE_WALL);
    }

    @Test
    void noCartNoChoiceAndTiesGoToTheFirstGiven() {
        assertThat(CartChoice.choose(new Cell(1, 1), List.of(), ROOM, CartChoice.Order.NEAREST)).isEmpty();
        CartState twin = new CartState("cart9", DOWN_THE_LANE.cell(), null);
        assertThat(CartChoice.choose(new Cell(1, 1), List.of(DOWN_THE_LANE, twin), ROOM, CartChoice.Order.NEAREST))
                .contains(DOWN_THE_LANE);
    }

    /**
     * Two doors: the robot's door is the left one (nearer to it). Behind it, the deeper cart goes first, then the
     * other; only then a cart behind the right door, though one stands nearer the robot by path than the deep one.
     */
    @Test
    void theDeepestCartBehindTheDoorTheRobotReachesFirst() {
        Grid twoDoors = Grid.parse(String.join("\n",
                "###########",
                "#d........#",
                "##D#####D##",
                "#uuuuuuuuu#",
                "#uuuuuuuuu#",
                "#uuuuuuuuu#",
                "###########"));
        CartState shallowLeft = new CartState("cart1", new Cell(2, 3), null);
        CartState deepLeft = new CartState("cart2", new Cell(1, 5), null);
        CartState shallowRight = new CartState("cart3", new Cell(8, 3), null);
        Cell robot = new Cell(1, 1);
        List<CartState> carts = List.of(shallowLeft, shallowRight, deepLeft);
        CartChoice.Order order = CartChoice.Order.DEEPEST_BEHIND_NEAREST_DOOR;
        assertThat(CartChoice.choose(robot, carts, twoDoors, order)).contains(deepLeft);
        assertThat(CartChoice.choose(robot, List.of(shallowLeft, shallowRight), twoDoors, order)).contains(shallowLeft);
        assertThat(CartChoice.choose(robot, List.of(shallowRight), twoDoors, order)).contains(shallowRight);
        assertThat(CartChoice.choose(robot, carts, twoDoors, CartChoice.Order.FARTHEST))
                .as("the farthest by path is behind the other door").contains(shallowRight);
    }
}
