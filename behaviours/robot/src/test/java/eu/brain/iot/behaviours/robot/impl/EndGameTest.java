package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.CartBudget;
import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;

/** At the end of the work a robot leaves a cart to another robot that will be done with it sooner. */
class EndGameTest {

    /** Two doors, (5,3) and (35,3), 30 cells apart; the docks along the top. */
    private static final Grid WIDE = Grid.parse(String.join("\n",
            "#########################################",
            "#ddddddddddddddddddddddddddddddddddddddd#",
            "#.......................................#",
            "#####D#############################D#####",
            "#uuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu#",
            "#uuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu#",
            "#uuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu#",
            "#########################################"));
    private static final Cell LEFT_DOCK = new Cell(5, 1);
    private static final Cell RIGHT_DOCK = new Cell(35, 1);
    private static final CartState BEHIND_RIGHT = new CartState("right", new Cell(36, 5), null);
    private static final CartState BEHIND_LEFT = new CartState("left", new Cell(4, 5), null);
    private static final List<RobotState> BOTH = List.of(docked("robot1", LEFT_DOCK), docked("robot2", RIGHT_DOCK));

    @Test
    void whileThereAreMoreCartsThanOtherRobotsEveryCartIsWorthTaking() {
        List<CartState> carts = List.of(BEHIND_RIGHT, BEHIND_LEFT);
        assertThat(EndGame.worthTaking(LEFT_DOCK, carts, List.of(new EndGame.Other(RIGHT_DOCK, 0)),
                new DoorShares(), WIDE)).containsExactlyElementsOf(carts);
    }

    @Test
    void aCartBehindAFarDoorIsLeftToARobotDockedNearItThatIsBackSoon() {
        List<EndGame.Other> others = List.of(new EndGame.Other(RIGHT_DOCK, 4), new EndGame.Other(new Cell(20, 1), 0));
        assertThat(EndGame.worthTaking(LEFT_DOCK, List.of(BEHIND_RIGHT), others, new DoorShares(), WIDE))
                .as("30 cells each way from here; 4 steps until the other is back, 2 from its dock").isEmpty();
        assertThat(EndGame.worthTaking(LEFT_DOCK, List.of(BEHIND_RIGHT, BEHIND_LEFT), others, new DoorShares(), WIDE))
                .as("its own door's cart it takes").containsExactly(BEHIND_LEFT);
    }

    @Test
    void aCartIsTakenWhenNoOtherRobotWouldBeDoneWithItSoonerByTheMargin() {
        DoorShares shares = new DoorShares();
        // the other is back in 50 steps: 50 + 2 x 2 + 10 is not under 2 x 32, this robot is done as soon
        assertThat(EndGame.worthTaking(LEFT_DOCK, List.of(BEHIND_RIGHT), List.of(new EndGame.Other(RIGHT_DOCK, 50),
                new EndGame.Other(new Cell(6, 1), 0)), shares, WIDE)).containsExactly(BEHIND_RIGHT);
        assertThat(EndGame.worthTaking(LEFT_DOCK, List.of(BEHIND_RIGHT), List.of(new EndGame.Other(RIGHT_DOCK, 49),
                new EndGame.Other(new Cell(6, 1), 0)), shares, WIDE)).as("back a step sooner: left to it").isEmpty();
        // two robots docked side by side: neither leaves the cart to the other for a step or two
        assertThat(EndGame.worthTaking(new Cell(34, 1), List.of(BEHIND_RIGHT), List.of(new EndGame.Other(RIGHT_DOCK,
                0)), shares, WIDE)).containsExactly(BEHIND_RIGHT);
    }

    @Test
    void theErrandTableGivesTheLastCartToTheRobotDockedNearItsDoor() {
        Errands errands = robotsAtBothDoors();

        assertThat(errands.claim("robot1", LEFT_DOCK, List.of(BEHIND_RIGHT), WIDE, BOTH)).isEmpty();
        assertThat(errands.claim("robot2", RIGHT_DOCK, List.of(BEHIND_RIGHT), WIDE, BOTH))
                .hasValueSatisfying(e -> assertThat(e.cart()).isEqualTo("right"));
    }

    @Test
    void noCartIsLeftToARobotThatLiftedAsManyAsTheModelLetsIt() {
        Errands errands = robotsAtBothDoors();
        for (int i = 0; i < CartBudget.PER_ROBOT; i++) { // robot2's errands, each ended: back at its dock
            CartState cart = new CartState("c" + i, new Cell(30 + i, 6), null);
            assertThat(errands.claim("robot2", RIGHT_DOCK, List.of(cart), WIDE, BOTH)).isPresent();
            errands.docked("robot2");
        }

        assertThat(errands.claim("robot1", LEFT_DOCK, List.of(BEHIND_RIGHT), WIDE, BOTH))
                .as("robot2 stays docked for good: robot1 takes the cart").isPresent();
    }

    /** robot1 docked by the left door, robot2 by the right one, both idle ({@link #BOTH}). */
    private static Errands robotsAtBothDoors() {
        Errands errands = new Errands(CartRelease.continuous(CartRelease.ROBOTS_PER_DOOR));
        errands.seen("robot1", LEFT_DOCK, true);
        errands.seen("robot2", RIGHT_DOCK, true);
        return errands;
    }

    private static RobotState docked(String id, Cell dock) {
        return new RobotState(id, dock, "N", Grid.DOCKING, false, RobotState.DETECTS_NOTHING, null, null, null, null,
                null, true);
    }

    @Test
    void aRobotOnItsWayIsBackAfterTheCellsOnItsWay() {
        assertThat(EndGame.stepsUntilBack(new Cell(10, 5), new Cell(10, 2), new Cell(12, 1))).isEqualTo(3 + 3);
        assertThat(EndGame.stepsUntilBack(new Cell(10, 5), null, new Cell(12, 1))).isEqualTo(6);
    }
}
