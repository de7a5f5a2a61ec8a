package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;

/** The errand table's rules on small maps: where carts go in storage, taking robots over, failed go-tos. */
class ErrandsTest {

    /**
     * Storage that spans the whole width between the door and the docks, as in robot-sim's generated warehouses:
     * carriers come up from the door (row 7), the docks are on top. Filling it must never wall a free storage cell
     * in: every cart up to the last finds a cell a robot carrying it can reach (the 60x30 warehouse's last three
     * robots found none).
     */
    private static final Grid BAND = Grid.parse(String.join("\n",
            "##############",
            "#dddddddddddd#",
            "#............#",
            "#ssssssssssss#",
            "#ssssssssssss#",
            "#ssssssssssss#",
            "#............#",
            "######D#######",
            "#uuuuuuuuuuuu#",
            "##############"));
    /** The robots of the fleet the claims are made in. */
    private static final int FLEET = 6;

    @Test
    void storageIsFilledToTheLastCellWithoutWallingAnyIn() {
        Errands errands = new Errands(6);
        Cell cartCell = new Cell(6, 8);
        List<CartState> carts = new ArrayList<>();
        int storage = BAND.cells(Grid.STORAGE).size();
        for (int n = 0; n < storage; n++) {
            int k = n % 12 + 1; // twelve robots, each with a dock of its own along the top row
            String robot = "robot" + k;
            Cell dock = new Cell(k, 1);
            errands.seen(robot, dock, true);
            carts.add(new CartState("cart" + n, cartCell, null));
            assertThat(errands.claim(robot, dock, carts, BAND, FLEET)).as("cart %d claimed", n).isPresent();
            Optional<Errands.Errand> e = errands.lifted(robot, cartCell, carriedBy(carts, n, robot), BAND);
            assertThat(e).as("a storage cell for cart %d of %d (placed so far: %s)", n + 1, storage, carts)
                    .isPresent();
            Cell drop = e.get().drop();
            assertThat(BAND.path(cartCell, drop, floor(carts))).as("cart %d can be carried to %s", n, drop)
                    .isNotNull();
            carts.set(n, new CartState("cart" + n, drop, null)); // put down there
            errands.placed(robot);
            errands.docked(robot);
        }
        assertThat(carts).extracting(CartState::cell).doesNotHaveDuplicates()
                .allMatch(c -> BAND.area(c) == Grid.STORAGE);
    }

    @Test
    void anErrandPlannedAnewKeepsTheCartARobotCarriesAndGivesBackOneItWentFor() {
        Errands errands = new Errands(6);
        Cell cartCell = new Cell(6, 8);
        List<CartState> carts = new ArrayList<>(List.of(new CartState("cart0", cartCell, null),
                new CartState("cart1", new Cell(7, 8), null)));
        errands.seen("robot1", new Cell(1, 1), true);
        errands.seen("robot2", new Cell(2, 1), true);
        assertThat(errands.claim("robot1", new Cell(1, 1), carts, BAND, FLEET)).isPresent();
        assertThat(errands.claim("robot2", new Cell(2, 1), carts, BAND, FLEET)).isPresent();
        Cell drop = errands.lifted("robot1", cartCell, carriedBy(carts, 0, "robot1"), BAND).orElseThrow().drop();

        errands.release("robot1"); // its go-tos to storage refused too often (its node handing it over)
        Errands.Errand kept = errands.of("robot1");
        assertThat(kept).as("only robot1 can bring its cart to storage").isNotNull();
        assertThat(kept.leg()).isEqualTo(Errands.Leg.TO_STORAGE);
        assertThat(kept.cart()).isEqualTo("cart0");
        assertThat(kept.drop()).as("a storage cell chosen again as it goes").isNull();
        assertThat(errands.lifted("robot1", cartCell, carriedBy(carts, 0, "robot1"), BAND)).isPresent()
                .get().extracting(Errands.Errand::drop).as("its old cell is free again").isEqualTo(drop);

        Errands.Errand toCart = errands.of("robot2");
        assertThat(toCart.leg()).isEqualTo(Errands.Leg.TO_CART);
        errands.release("robot2"); // on its way to a cart: the cart goes back to the table
        assertThat(errands.of("robot2").cart()).isNull();
        assertThat(errands.claimed(toCart.cart())).as("claimable again").isFalse();
    }

    @Test
    void aCartOnTheFloorOutsideStorageGoesBackToTheTableAndOneInStorageCountsAsPlaced() {
        Errands errands = new Errands(6);
        Cell cartCell = new Cell(5, 8); // beside the doorway (6,8), which stays free
        List<CartState> carts = new ArrayList<>(List.of(new CartState("cart0", cartCell, null),
                new CartState("cart1", new Cell(7, 8), null)));
        errands.seen("robot1", new Cell(1, 1), true);
        errands.seen("robot2", new Cell(2, 1), true);
        assertThat(errands.claim("robot1", new Cell(1, 1), carts, BAND, FLEET)).isPresent();
        errands.lifted("robot1", cartCell, carriedBy(carts, 0, "robot1"), BAND).orElseThrow();

        errands.cartDown("robot1", cartCell, BAND); // its pick failed: cart0 still stands on the table
        assertThat(errands.of("robot1").leg()).as("robot1 carries nothing").isEqualTo(Errands.Leg.NONE);
        assertThat(errands.claimed("cart0")).as("cart0 claimable again").isFalse();
        assertThat(errands.claim("robot1", new Cell(6, 6), carts, BAND, FLEET)).as("a cart to fetch again").isPresent();

        assertThat(errands.claim("robot2", new Cell(2, 1), carts, BAND, FLEET)).isPresent();
        Cell carriedFrom = errands.of("robot2").cartCell();
        Cell drop = errands.lifted("robot2", carriedFrom, carriedBy(carts, 1, "robot2"), BAND).orElseThrow().drop();
        errands.cartDown("robot2", drop, BAND); // put down in storage before the behaviour saw it placed
        assertThat(errands.of("robot2").leg()).as("it heads home").isEqualTo(Errands.Leg.TO_DOCK);
        assertThat(errands.delivered()).isEqualTo(1);
    }

    @Test
    void aRobotGoingHomeWithTheCartItsPlaceLostCarriesItBackAndItCountsOnceDelivered() {
        Errands errands = new Errands(6);
        List<CartState> carts = new ArrayList<>(List.of(new CartState("cart1", new Cell(7, 8), null)));
        errands.seen("robot1", new Cell(2, 1), true);
        errands.claim("robot1", new Cell(2, 1), carts, BAND, FLEET).orElseThrow();
        Cell drop = errands.lifted("robot1", new Cell(7, 8), carriedBy(carts, 0, "robot1"), BAND).orElseThrow().drop();
        errands.placed("robot1"); // the place is sent, then lost: the robot heads home with cart1

        errands.carryBack("robot1", "cart1");
        Errands.Errand back = errands.of("robot1");
        assertThat(back.leg()).isEqualTo(Errands.Leg.TO_STORAGE);
        assertThat(back.cart()).isEqualTo("cart1");
        assertThat(back.dock()).as("its dock kept").isEqualTo(new Cell(2, 1));
        assertThat(errands.delivered()).as("not delivered").isZero();
        Cell again = errands.lifted("robot1", new Cell(2, 3), carriedBy(carts, 0, "robot1"), BAND).orElseThrow()
                .drop();
        assertThat(BAND.area(again)).as("a storage cell again (the first was %s)", drop).isEqualTo(Grid.STORAGE);
        errands.placed("robot1");
        assertThat(errands.delivered()).isEqualTo(1);
    }

    @Test
    void aRobotTakenOverCarryingACartCarriesItToStorageAndGetsAFreeDock() {
        Errands errands = new Errands(6);
        RobotState docked = robot("robot1", new Cell(1, 1), null, null, null);
        RobotState carrier = robot("robot2", new Cell(4, 6), "cart7", "running", new Cell(5, 4));
        List<CartState> carts = List.of(new CartState("cart7", new Cell(4, 6), "robot2"));
        List<RobotState> all = List.of(docked, carrier);

        assertThat(errands.adopt(docked, carts, BAND, all)).isTrue();
        assertThat(errands.of("robot1").leg()).isEqualTo(Errands.Leg.NONE);
        assertThat(errands.adopt(carrier, carts, BAND, all)).isTrue();
        Errands.Errand e = errands.of("robot2");
        assertThat(e.leg()).isEqualTo(Errands.Leg.TO_STORAGE);
        assertThat(e.cart()).isEqualTo("cart7");
        assertThat(e.drop()).as("the storage cell it was heading for").isEqualTo(new Cell(5, 4));
        assertThat(e.dock()).as("the nearest docking cell that is nobody's").isNotNull()
                .isNotEqualTo(new Cell(1, 1));
        assertThat(errands.adopt(carrier, carts, BAND, all)).as("taken over once").isFalse();
    }

    @Test
    void aRobotTakenOverOnItsWayToACartKeepsThatCartAndOneOutWithoutWorkGoesHome() {
        Errands errands = new Errands(6);
        RobotState toCart = robot("robot1", new Cell(4, 6), null, "running", new Cell(7, 8));
        RobotState out = robot("robot2", new Cell(3, 2), null, "finished", null);
        List<CartState> carts = List.of(new CartState("cart1", new Cell(7, 8), null));
        List<RobotState> all = List.of(toCart, out);

        errands.adopt(toCart, carts, BAND, all);
        errands.adopt(out, carts, BAND, all);

        assertThat(errands.of("robot1").leg()).isEqualTo(Errands.Leg.TO_CART);
        assertThat(errands.of("robot1").cart()).isEqualTo("cart1");
        assertThat(errands.of("robot2").leg()).isEqualTo(Errands.Leg.TO_DOCK);
        assertThat(errands.workLeft(carts, BAND)).as("cart1 is claimed").isFalse();
    }

    @Test
    void aRobotSentOutOfTheWayWithoutAnErrandGoesHome() {
        Errands errands = new Errands(6);
        RobotState docked = robot("robot1", new Cell(1, 1), null, null, null);
        errands.adopt(docked, List.of(), BAND, List.of(docked));
        assertThat(errands.knows("robot1")).isTrue();

        errands.seen(robot("robot1", new Cell(1, 2), null, "running", new Cell(1, 2)), BAND);
        assertThat(errands.of("robot1").leg()).as("still on its way out").isEqualTo(Errands.Leg.NONE);
        errands.seen(robot("robot1", new Cell(1, 2), null, "finished", new Cell(1, 2)), BAND);
        assertThat(errands.of("robot1").leg()).isEqualTo(Errands.Leg.TO_DOCK);
        assertThat(errands.of("robot1").dock()).isEqualTo(new Cell(1, 1));
    }

    @Test
    void aFailedGoToToTheStorageCellGivesAnotherCellAndAFailedOneToTheCartGivesTheCartBack() {
        Errands errands = new Errands(6);
        Cell first = liftedCart1(errands);

        // another cart stands there now (put down since; the device model did not show it yet)
        List<CartState> now = List.of(new CartState("cart1", new Cell(4, 6), "robot1"),
                new CartState("cart9", first, null));
        assertThat(errands.goalFailed("robot1", new Cell(4, 6), first, now, BAND)).isTrue();
        assertThat(errands.of("robot1").drop()).isNotNull().isNotEqualTo(first);
        assertThat(errands.goalFailed("robot1", new Cell(4, 6), new Cell(1, 1), now, BAND))
                .as("a go-to that was not the errand's").isFalse();

        errands.seen("robot2", new Cell(3, 1), true);
        List<CartState> floor = List.of(new CartState("cart2", new Cell(8, 8), null));
        errands.placed("robot1");
        errands.docked("robot1");
        errands.claim("robot2", new Cell(3, 1), floor, BAND, FLEET);
        assertThat(errands.goalFailed("robot2", new Cell(3, 1), new Cell(8, 8), floor, BAND)).isTrue();
        assertThat(errands.of("robot2").leg()).isEqualTo(Errands.Leg.NONE);
        assertThat(errands.workLeft(floor, BAND)).as("cart2 back on the table").isTrue();
    }

    @Test
    void aCarrierWalledInByCartsPutDownSinceGetsACellItCanReachOrPutsItsCartDownWhereItStands() {
        Errands errands = new Errands(6);
        Cell drop = liftedCart1(errands);
        Cell at = new Cell(6, 4); // in storage, on its way
        assertThat(drop).isNotEqualTo(at);

        // every storage cell around it taken by carts put down since: boxed in on its own cell
        List<CartState> boxedIn = new ArrayList<>(List.of(new CartState("cart1", at, "robot1")));
        BAND.neighbours(at).forEach(n -> boxedIn.add(new CartState("cart-" + n, n, null)));
        assertThat(BAND.path(at, drop, floor(boxedIn))).as("no way to its storage cell with a cart").isNull();
        assertThat(errands.walledIn("robot1", at, drop, boxedIn, BAND)).isTrue();
        assertThat(errands.of("robot1").drop()).as("it puts its cart down where it stands, in storage").isEqualTo(at);

        // one cart away: another cell it can reach
        Errands again = new Errands(6);
        Cell first = liftedCart1(again);
        List<CartState> oneWall = new ArrayList<>(List.of(new CartState("cart1", new Cell(6, 6), "robot1")));
        BAND.neighbours(first).forEach(n -> oneWall.add(new CartState("cart-" + n, n, null)));
        assertThat(again.walledIn("robot1", new Cell(6, 6), first, oneWall, BAND)).isTrue();
        Cell next = again.of("robot1").drop();
        assertThat(next).isNotNull().isNotEqualTo(first);
        assertThat(BAND.path(new Cell(6, 6), next, floor(oneWall))).as("reachable with its cart").isNotNull();
    }

    /** robot1, docked at (2,1), claims cart1 at (4,8) and lifts it: @return the storage cell it is given */
    private static Cell liftedCart1(Errands errands) {
        Cell dock = new Cell(2, 1);
        Cell cartCell = new Cell(4, 8);
        errands.seen("robot1", dock, true);
        errands.claim("robot1", dock, List.of(new CartState("cart1", cartCell, null)), BAND, FLEET);
        return errands.lifted("robot1", cartCell, List.of(new CartState("cart1", cartCell, "robot1")), BAND)
                .orElseThrow().drop();
    }

    private static List<CartState> carriedBy(List<CartState> carts, int n, String robot) {
        List<CartState> now = new ArrayList<>(carts);
        now.set(n, new CartState("cart" + n, carts.get(n).cell(), robot));
        return now;
    }

    private static Set<Cell> floor(List<CartState> carts) {
        Set<Cell> cells = new HashSet<>();
        carts.stream().filter(c -> c.carriedBy() == null).forEach(c -> cells.add(c.cell()));
        return cells;
    }

    /** The paper's warehouse: three docks on the top row with a docking cell between each two. */
    static final Grid PAPER = Grid.parse(String.join("\n",
            "####################",
            "#dRdRdRd....ssssss.#",
            "#ddddddd....ssssss.#",
            "#..................#",
            "#..................#",
            "#########D##########",
            "#uuuuuuuuuuuuuuuuuu#",
            "#uuCuuuuuuCuuuuuCuu#",
            "#uuuuuuuuuuuuuuuuuu#",
            "####################"));

    @Test
    void robotsTakenOverOnTheFloorGetDocksNoTwoOfWhichAreSideBySide() {
        Errands errands = new Errands(4);
        List<RobotState> all = List.of(robot("robot1", new Cell(11, 3), null, "running", new Cell(8, 1)),
                robot("robot2", new Cell(12, 2), null, "running", new Cell(8, 1)),
                robot("robot3", new Cell(10, 1), null, "running", new Cell(8, 1)));
        all.forEach(r -> errands.adopt(r, List.of(), PAPER, all));

        List<Cell> docks = all.stream().map(r -> errands.of(r.id()).dock()).toList();
        assertThat(docks).doesNotContainNull().doesNotHaveDuplicates()
                .allMatch(d -> PAPER.area(d) == Grid.DOCKING);
        for (Cell d : docks) {
            assertThat(PAPER.neighbours(d)).as("the neighbours of %s", d).doesNotContainAnyElementsOf(docks);
        }
    }

    @Test
    void robotsTakenOverOnTheFloorGoBackToTheDocksAnEarlierRunLearnt() {
        Errands first = new Errands(4);
        List<RobotState> docked = List.of(robot("robot1", new Cell(2, 1), null, null, null),
                robot("robot2", new Cell(4, 1), null, null, null), robot("robot3", new Cell(6, 1), null, null, null));
        docked.forEach(r -> first.adopt(r, List.of(), PAPER, docked));
        Map<String, Cell> learnt = first.docks();
        assertThat(learnt).containsEntry("robot1", new Cell(2, 1)).containsEntry("robot3", new Cell(6, 1));

        Errands again = new Errands(4); // the behaviour started again while the robots are out
        again.remember(learnt);
        List<RobotState> out = List.of(robot("robot1", new Cell(11, 3), null, "running", new Cell(12, 1)),
                robot("robot2", new Cell(12, 2), null, "finished", null),
                robot("robot3", new Cell(7, 2), null, "running", new Cell(12, 2)));
        out.forEach(r -> again.adopt(r, List.of(), PAPER, out));
        assertThat(again.docks()).isEqualTo(learnt);
        assertThat(again.of("robot2").leg()).isEqualTo(Errands.Leg.TO_DOCK);
    }

    private static RobotState robot(String id, Cell cell, String cart, String missionState, Cell goal) {
        return new RobotState(id, cell, "N", BAND.area(cell), "running".equals(missionState), 0, cart,
                missionState == null ? null : 1L, missionState == null ? null : "goto", missionState, goal, true);
    }
}
