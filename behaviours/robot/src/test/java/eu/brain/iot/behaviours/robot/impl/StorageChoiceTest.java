package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/** Which storage cell a carried cart goes to: reachable, walling nothing in, shortest for the rest of the trip. */
class StorageChoiceTest {

    /** A storage pocket two cells deep: the inner cell (1,2) is reached only through the outer one (2,2). */
    private static final Grid POCKET = Grid.parse(String.join("\n",
            "######",
            "##d..#",
            "#ss..#",
            "##...#",
            "###D##",
            "#uuuu#",
            "######"));

    @Test
    void theInnerCellOfAPocketIsFilledBeforeTheOuterOneThatWouldWallItIn() {
        Cell from = new Cell(3, 5);
        Cell dock = new Cell(2, 1);
        assertThat(StorageChoice.choose(POCKET, from, dock, Set.of(), List.of())).isEqualTo(new Cell(1, 2));
        // with the inner cell given to another robot's cart in flight, the outer one would wall it in
        assertThat(StorageChoice.choose(POCKET, from, dock, Set.of(new Cell(1, 2)), List.of(new Cell(1, 2))))
                .as("the outer cell would cut the cell another robot carries its cart to").isNull();
        // once that cart is down, the outer cell is free to take
        assertThat(StorageChoice.choose(POCKET, from, dock, Set.of(new Cell(1, 2)), List.of()))
                .isEqualTo(new Cell(2, 2));
    }

    @Test
    void noCellWhenCartsOnTheFloorBarTheWay() {
        Set<Cell> carts = Set.of(new Cell(3, 4)); // a cart standing in the doorway
        assertThat(StorageChoice.choose(POCKET, new Cell(3, 5), new Cell(2, 1), carts, List.of())).isNull();
    }
}
