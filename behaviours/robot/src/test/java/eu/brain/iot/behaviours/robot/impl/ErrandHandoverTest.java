package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;

/**
 * The errand table the instance that drives the fleet shares, read back by the one that takes over, and what the
 * takeover makes of it: robots continue their errands where the device model alone would send them home.
 */
class ErrandHandoverTest {

    static final Grid MAP = Grid.parse(String.join("\n",
            "##############",
            "#dddddddddddd#",
            "#............#",
            "#ssssssssssss#",
            "#ssssssssssss#",
            "#............#",
            "######D#######",
            "#uuuuuuuuuuuu#",
            "#uuuuuuuuuuuu#",
            "##############"));

    @Test
    void aTableReadsBackAsItWasWritten() {
        Errands.Errand toCart = new Errands.Errand("robot1", Errands.Leg.TO_CART, "cart3", new Cell(4, 8), null,
                new Cell(1, 1));
        Errands.Errand toStorage = new Errands.Errand("robot2", Errands.Leg.TO_STORAGE, "cart1", new Cell(5, 7),
                new Cell(6, 3), new Cell(2, 1));
        String text = ErrandHandover.write(List.of(toCart, toStorage),
                Map.of("robot1", new Cell(1, 1), "robot2", new Cell(2, 1), "robot3", new Cell(3, 1)),
                Map.of("robot1", 2, "robot2", 1));

        ErrandHandover.Table table = ErrandHandover.read(text, MAP);

        assertThat(table.errands()).containsOnlyKeys("robot1", "robot2");
        assertThat(table.errands().get("robot1")).isEqualTo(toCart);
        assertThat(table.errands().get("robot2")).isEqualTo(toStorage);
        assertThat(table.docks()).containsEntry("robot3", new Cell(3, 1)).hasSize(3);
        assertThat(table.given()).containsEntry("robot1", 2).containsEntry("robot3", 0);
    }

    @Test
    void linesThatDoNotReadOrLieOffTheMapAreLeftOut() {
        String text = String.join("\n",
                "robot1 1,1 0 TO_CART cart1 4,8 -",
                "robot2 2,1 0 FLYING cart2 4,8 -", // no such leg
                "robot3 99,99 0 TO_DOCK - - -", // a dock off the map
                "robot4 4,1 0 TO_CART cart 4 4,8 -", // too many fields
                "robot 5 1 0 NONE - - -",
                "robot6 6,1 x NONE - - -", // a count that is not one
                "");

        ErrandHandover.Table table = ErrandHandover.read(text, MAP);

        assertThat(table.errands()).containsOnlyKeys("robot1");
        assertThat(table.docks()).containsOnlyKeys("robot1");
        assertThat(ErrandHandover.read(null, MAP).errands()).isEmpty();
    }

    @Test
    void whatTheLeaderSharedIsTakenOnceByTheInstanceThatTakesOver() {
        ErrandHandover handover = new ErrandHandover();
        assertThat(handover.take(MAP)).as("nothing heard").isNull();

        handover.heard("robot1 1,1 1 TO_CART cart1 4,8 -\n");
        handover.heard("robot1 1,1 1 TO_DOCK - - -\n"); // the last beat counts

        assertThat(handover.take(MAP).errands().get("robot1").leg()).isEqualTo(Errands.Leg.TO_DOCK);
        assertThat(handover.take(MAP)).as("taken").isNull();
    }

    @Test
    void aLeaderSharesItsTableOncePerBeatAndNothingOnceItStandsBy() {
        ErrandHandover handover = new ErrandHandover();
        handover.share(() -> "robot1 1,1 0 NONE - - -\n");
        handover.share(() -> "read again within a beat");

        assertThat(handover.shared()).isEqualTo("robot1 1,1 0 NONE - - -\n");
        handover.standBy();
        assertThat(handover.shared()).isEmpty();
    }

    @Test
    void aTakeoverContinuesTheErrandsTheDeviceModelCannotShow() {
        Errands before = new Errands(6);
        Cell cart1 = new Cell(4, 8);
        Cell cart2 = new Cell(9, 8);
        RobotState goer = robot("robot1", new Cell(1, 1), null, null, null);
        RobotState carrier = robot("robot2", new Cell(2, 1), null, null, null);
        RobotState other = robot("robot3", new Cell(3, 1), null, null, null);
        List<RobotState> docked = List.of(goer, carrier, other);
        List<CartState> floor = List.of(new CartState("cart1", cart1, null), new CartState("cart2", cart2, null));
        docked.forEach(r -> before.adopt(r, floor, MAP, docked));
        assertThat(before.claim("robot1", goer.cell(), floor, MAP, docked)).isPresent();
        assertThat(before.claim("robot2", carrier.cell(), floor, MAP, docked)).isPresent();
        String robot2Cart = before.of("robot2").cart();
        String robot1Cart = before.of("robot1").cart();
        Cell robot2CartCell = before.of("robot2").cartCell();
        List<CartState> lifting = List.of(new CartState(robot1Cart, before.of("robot1").cartCell(), null),
                new CartState(robot2Cart, robot2CartCell, "robot2"));
        Cell drop = before.lifted("robot2", robot2CartCell, lifting, MAP).orElseThrow().drop();

        // the next instance: robot1 drives a leg of its path to the cart (its goal is the leg's end, on no cart),
        // robot2 carries its cart along a leg, robot3 stands out on the floor where the driver before sent it
        Errands after = new Errands(6);
        after.inherit(ErrandHandover.read(before.handover(), MAP));
        RobotState goerNow = robot("robot1", new Cell(6, 5), null, "running", new Cell(6, 6));
        RobotState carrierNow = robot("robot2", new Cell(6, 6), robot2Cart, "running", new Cell(6, 5));
        RobotState otherNow = robot("robot3", new Cell(8, 2), null, "finished", null);
        List<RobotState> now = List.of(goerNow, carrierNow, otherNow);
        List<CartState> carts = List.of(new CartState(robot1Cart, before.of("robot1").cartCell(), null),
                new CartState(robot2Cart, new Cell(6, 6), "robot2"));
        now.forEach(r -> after.adopt(r, carts, MAP, now));

        assertThat(after.of("robot1")).extracting(Errands.Errand::leg, Errands.Errand::cart)
                .containsExactly(Errands.Leg.TO_CART, robot1Cart);
        assertThat(after.of("robot2")).extracting(Errands.Errand::leg, Errands.Errand::drop)
                .as("the storage cell it was given").containsExactly(Errands.Leg.TO_STORAGE, drop);
        assertThat(after.of("robot3")).extracting(Errands.Errand::leg, Errands.Errand::dock)
                .as("home to the dock it was first seen on").containsExactly(Errands.Leg.TO_DOCK, new Cell(3, 1));
        assertThat(after.docks()).isEqualTo(before.docks());
    }

    @Test
    void withoutAHandoverTheSameRobotsAreTakenOverFromTheDeviceModelAlone() {
        Errands fresh = new Errands(6);
        RobotState goerNow = robot("robot1", new Cell(6, 5), null, "running", new Cell(6, 6));
        List<CartState> carts = List.of(new CartState("cart1", new Cell(4, 8), null));

        fresh.adopt(goerNow, carts, MAP, List.of(goerNow));

        assertThat(fresh.of("robot1").leg()).as("its cart is not known: home").isEqualTo(Errands.Leg.TO_DOCK);
    }

    @Test
    void aRobotHeadingForACartAnotherWentForLeavesItToThatOne() {
        Errands after = new Errands(6);
        after.inherit(ErrandHandover.read("robot1 1,1 1 TO_CART cart1 4,8 -\nrobot2 2,1 0 NONE - - -\n", MAP));
        RobotState passing = robot("robot2", new Cell(3, 8), null, "running", new Cell(4, 8)); // a leg's end
        RobotState goer = robot("robot1", new Cell(6, 6), null, "running", new Cell(6, 7));
        List<CartState> carts = List.of(new CartState("cart1", new Cell(4, 8), null));
        List<RobotState> now = List.of(passing, goer);

        now.forEach(r -> after.adopt(r, carts, MAP, now));

        assertThat(after.of("robot2").leg()).isEqualTo(Errands.Leg.TO_DOCK);
        assertThat(after.of("robot1").cart()).isEqualTo("cart1");
    }

    @Test
    void aRobotNotPolledYetKeepsItsCartFromOthersClaimsUntilTheHoldEnds() {
        Errands after = new Errands(6);
        after.inherit(ErrandHandover.read("robot1 1,1 1 TO_CART cart1 4,8 -\nrobot2 2,1 0 NONE - - -\n", MAP));
        RobotState docked = robot("robot2", new Cell(2, 1), null, null, null);
        List<CartState> carts = List.of(new CartState("cart1", new Cell(4, 8), null));
        after.adopt(docked, carts, MAP, List.of(docked)); // robot1's node died: nobody polls it yet

        assertThat(after.claimed("cart1")).isTrue();
        assertThat(after.claim("robot2", docked.cell(), carts, MAP, List.of(docked))).isEmpty();

        after.inherit(ErrandHandover.Table.EMPTY); // the hold ended: robot1 was not polled since
        assertThat(after.claim("robot2", docked.cell(), carts, MAP, List.of(docked))).isPresent();
    }

    @Test
    void theStorageCellOfACarrierNotPolledYetIsGivenToNoOtherCart() {
        Cell only = new Cell(6, 3);
        Errands after = new Errands(6);
        after.inherit(ErrandHandover.read("robot1 1,1 1 TO_STORAGE cart1 4,8 6,3\n", MAP));
        List<CartState> carts = List.of(new CartState("cart2", new Cell(5, 7), "robot2"));
        after.adopt(robot("robot2", new Cell(5, 7), "cart2", "running", new Cell(5, 6)), carts, MAP, List.of());

        Cell drop = after.lifted("robot2", new Cell(5, 7), carts, MAP).orElseThrow().drop();

        assertThat(drop).isNotEqualTo(only);
    }

    @Test
    void theHoldEndsOnceAfterItsTime() {
        ErrandHandover handover = new ErrandHandover();
        handover.heard("robot1 1,1 1 TO_DOCK - - -\n");
        long taken = System.nanoTime();
        handover.take(MAP);

        assertThat(handover.holdEnded(taken)).isFalse();
        assertThat(handover.holdEnded(taken + ErrandHandover.HOLD_NANOS + 1_000_000_000L)).isTrue();
        assertThat(handover.holdEnded(taken + 2 * ErrandHandover.HOLD_NANOS)).as("once").isFalse();
    }

    private static RobotState robot(String id, Cell cell, String cart, String missionState, Cell goal) {
        return new RobotState(id, cell, "N", MAP.area(cell), "running".equals(missionState), 0, cart,
                missionState == null ? null : 1L, missionState == null ? null : "goto", missionState, goal, true);
    }
}
