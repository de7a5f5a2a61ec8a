package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;

/** Which cart each robot goes for when the carts are scheduled over the fleet so that the last errand ends soonest. */
class CartScheduleTest {

    /** A lane with a dock at each end: an errand is twice the way from the dock, plus lifting and placing. */
    private static final Grid LANE = Grid.parse(String.join("\n",
            "#############",
            "#d.........d#",
            "#############"));
    private static final Cell LEFT = new Cell(1, 1);
    private static final Cell RIGHT = new Cell(11, 1);

    private static CartState cart(int x) {
        return new CartState("cart" + x, new Cell(x, 1), null);
    }

    private final CartSchedule schedule = new CartSchedule();

    @Test
    void anErrandIsTheWayToTheCartAndBackPlusLiftingAndPlacing() {
        assertThat(schedule.errand(LANE, LEFT, new Cell(4, 1))).isEqualTo(2 * 3 + CartSchedule.HANDLING_STEPS);
        assertThat(schedule.errand(LANE, LEFT, new Cell(4, 0))).as("in the wall").isEqualTo(-1);
    }

    /**
     * Three carts near the left dock, one near the right: the left robot takes the three (24 steps in all), the right
     * one the fourth; given a near one, the right robot would end at 28. Each starts with its longest errand.
     */
    @Test
    void theCartsAreSharedSoThatTheLastErrandEndsSoonestTheLongestFirst() {
        List<CartState> carts = List.of(cart(2), cart(3), cart(4), cart(10));
        List<CartSchedule.Worker> idle = List.of(new CartSchedule.Worker("left", LEFT, 0),
                new CartSchedule.Worker("right", RIGHT, 0));
        Map<String, List<CartState>> plan = schedule.plan(LANE, carts, idle);
        assertThat(plan.get("left")).containsExactly(cart(4), cart(3), cart(2));
        assertThat(plan.get("right")).containsExactly(cart(10));
        assertThat(schedule.choose("left", LANE, carts, idle)).contains(cart(4));
    }

    /**
     * One cart next to the right dock: its robot, back in 4 steps, ends it at 10; the idle left robot would end at 22
     * and stays docked. Back only in 30 steps, the right robot would end at 36: the left one goes.
     */
    @Test
    void aRobotStaysDockedWhenOneBackSoonerDoesTheCartInLessTime() {
        List<CartState> carts = List.of(cart(10));
        assertThat(schedule.choose("left", LANE, carts, List.of(new CartSchedule.Worker("left", LEFT, 0),
                new CartSchedule.Worker("right", RIGHT, 4)))).isEmpty();
        assertThat(schedule.choose("left", LANE, carts, List.of(new CartSchedule.Worker("left", LEFT, 0),
                new CartSchedule.Worker("right", RIGHT, 30)))).contains(cart(10));
    }

    /** Many carts near one dock: the robot docked far away takes some, the longest for it first being the nearest. */
    @Test
    void aRobotFarAwayHelpsWhereTheCartsAre() {
        List<CartState> carts = List.of(cart(2), cart(3), cart(4), cart(5), cart(6));
        Map<String, List<CartState>> plan = schedule.plan(LANE, carts, List.of(
                new CartSchedule.Worker("left", LEFT, 0), new CartSchedule.Worker("right", RIGHT, 0)));
        assertThat(plan.get("right")).isNotEmpty();
        int left = plan.get("left").stream().mapToInt(c -> schedule.errand(LANE, LEFT, c.cell())).sum();
        int right = plan.get("right").stream().mapToInt(c -> schedule.errand(LANE, RIGHT, c.cell())).sum();
        assertThat(Math.max(left, right)).as("all five by the left robot: 50 steps").isLessThan(50);
        assertThat(plan.values().stream().mapToInt(List::size).sum()).isEqualTo(5);
    }

    @Test
    void aCartNoRobotReachesIsGivenToNone() {
        Grid walled = Grid.parse(String.join("\n",
                "#######",
                "#d..#.#",
                "#######"));
        CartState inside = new CartState("cart1", new Cell(5, 1), null);
        assertThat(schedule.plan(walled, List.of(inside), List.of(new CartSchedule.Worker("r", LEFT, 0))))
                .isEmpty();
    }

    /** Through two doors: the errand table keeps a robot docked while the schedule gives its carts to others. */
    @Test
    void theErrandTableLetsARobotSetOffOnlyWithACartOfItsOwn() {
        Grid twoDoors = Grid.parse(String.join("\n",
                "#############",
                "#d.........d#",
                "#...........#",
                "###D#####D###",
                "#uuuuuuuuuuu#",
                "#############"));
        Errands errands = new Errands(CartRelease.continuous(10));
        RobotState left = docked("left", LEFT);
        RobotState right = docked("right", RIGHT);
        List<RobotState> robots = List.of(left, right);
        robots.forEach(r -> errands.adopt(r, List.of(), twoDoors, robots));
        List<CartState> carts = List.of(new CartState("near-right", new Cell(10, 4), null));

        assertThat(errands.scheduled("left", carts, twoDoors, robots)).isFalse();
        assertThat(errands.scheduled("right", carts, twoDoors, robots)).isTrue();
        assertThat(errands.claim("right", RIGHT, carts, twoDoors, robots).orElseThrow().cart())
                .isEqualTo("near-right");
        errands.newLook();
        assertThat(errands.scheduled("left", carts, twoDoors, robots)).as("claimed: nothing waits").isFalse();
    }

    private static RobotState docked(String id, Cell dock) {
        return new RobotState(id, dock, "N", Grid.DOCKING, false, RobotState.DETECTS_NOTHING, null, null, null, null,
                null, true);
    }
}
