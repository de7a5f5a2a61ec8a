package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;

/** Through several doors, each door's share of the robots out follows its carts not yet placed. */
class DoorSharesTest {

    /** Two doors, (2,3) on the left and (8,3) on the right; the docks along the top. */
    private static final Grid TWO_DOORS = Grid.parse(String.join("\n",
            "###########",
            "#ddddddddd#",
            "#.........#",
            "##D#####D##",
            "#uuuuuuuuu#",
            "#uuuuuuuuu#",
            "#uuuuuuuuu#",
            "###########"));
    private static final Cell LEFT = new Cell(2, 3);
    private static final Cell RIGHT = new Cell(8, 3);

    private static List<CartState> carts(String prefix, int x0, int count) {
        List<CartState> carts = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            carts.add(new CartState(prefix + i, new Cell(x0 + i % 3, 4 + i / 3), null));
        }
        return carts;
    }

    @Test
    void aCartIsBehindTheDoorwayNearestItByPath() {
        DoorShares shares = new DoorShares();
        assertThat(shares.doorOf(new Cell(1, 6), TWO_DOORS)).isEqualTo(LEFT);
        assertThat(shares.doorOf(new Cell(9, 4), TWO_DOORS)).isEqualTo(RIGHT);
        assertThat(shares.doorOf(new Cell(4, 5), TWO_DOORS)).isEqualTo(LEFT);
    }

    @Test
    void aDoorWithItsShareOfRobotsIsClosedToTheNextClaim() {
        DoorShares shares = new DoorShares();
        List<CartState> left = carts("l", 1, 6);   // 6 carts behind the left door
        List<CartState> right = carts("r", 7, 2);  // 2 behind the right one
        List<CartState> all = new ArrayList<>(left);
        all.addAll(right);
        // 4 robots out at most, shared by the carts not placed (unclaimed and out)
        assertThat(shares.behindOpenDoors(all, List.of(LEFT, LEFT), 4, TWO_DOORS))
                .as("left share 4 x 8/10, right 4 x 2/10: both under").containsExactlyElementsOf(all);
        assertThat(shares.behindOpenDoors(all, List.of(LEFT, LEFT, LEFT, LEFT), 4, TWO_DOORS))
                .as("left share 4 x 10/12 < 4 robots: the right door only").containsExactlyElementsOf(right);
        assertThat(shares.behindOpenDoors(all, List.of(LEFT, LEFT, LEFT, LEFT, RIGHT), 4, TWO_DOORS))
                .as("every door has its share: any door").containsExactlyElementsOf(all);
    }

    @Test
    void whenNoDoorIsUnderItsShareEveryDoorWithUnclaimedCartsIsOpenAndOneDoorHasNoShares() {
        DoorShares shares = new DoorShares();
        List<CartState> right = carts("r", 7, 3);
        List<Cell> out = List.of(RIGHT, RIGHT, RIGHT, RIGHT, RIGHT, RIGHT, LEFT, LEFT, LEFT, LEFT);
        assertThat(shares.behindOpenDoors(right, out, 8, TWO_DOORS))
                .as("right share 8 x 9/13 < 6 robots, left none unclaimed: the carts left are claimed all the same")
                .containsExactlyElementsOf(right);
        Grid oneDoor = Grid.parse(String.join("\n",
                "###########",
                "#ddddddddd#",
                "#.........#",
                "##D########",
                "#uuuuuuuuu#",
                "###########"));
        assertThat(new DoorShares().behindOpenDoors(right, List.of(new Cell(2, 3)), 1, oneDoor))
                .as("one door: no shares").containsExactlyElementsOf(right);
    }

    /**
     * The claims of a whole fleet at the start, robots taken left to right: the left door, with three times the
     * carts, gets three times the robots (by the nearest door alone, 5 and 3); robot8, nearest the right door, goes
     * left once the right door has its share.
     */
    @Test
    void theFirstClaimsOfAFleetFollowTheCartsBehindEachDoor() {
        Errands errands = new Errands(CartRelease.continuous(4)); // 8 robots out through 2 doors
        List<CartState> all = new ArrayList<>(carts("l", 1, 9));
        all.addAll(carts("r", 7, 3));
        List<Cell> doors = new ArrayList<>();
        DoorShares shares = new DoorShares();
        for (int x = 1; x <= 8; x++) {
            Optional<Errands.Errand> e = errands.claim("robot" + x, new Cell(x, 1), all, TWO_DOORS, 8);
            assertThat(e).as("robot%d claims", x).isPresent();
            doors.add(shares.doorOf(e.get().cartCell(), TWO_DOORS));
        }
        assertThat(doors).containsExactly(LEFT, LEFT, LEFT, LEFT, LEFT, RIGHT, RIGHT, LEFT);
    }
}
