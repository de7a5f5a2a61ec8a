package eu.brain.iot.robotsim.world;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * Over many seeds and random command sequences: two robots never share a cell, robots move at most one cell per step
 * and only onto passable cells (a doorway only while its door lets them), and carts are never lost or duplicated.
 */
class WorldPropertyTest {
    private static final int SEEDS = 150;
    private static final int STEPS = 120;

    @Test
    void invariantsHoldForRandomCommands() throws Exception {
        long carrySteps = 0;
        long nearMisses = 0;
        long doorways = 0;
        for (long seed = 1; seed <= SEEDS; seed++) {
            WarehouseMap map = seed % 3 == 0 ? WarehouseMap.paper()
                    : MapGenerator.generate(24, 18, 12 + (int) (seed % 7), 30, 2, seed);
            Sim sim = new Sim(map, SimRules.DEFAULT.withSeed(seed).withDoorOpenSteps((int) (seed % 4)));
            Random random = new Random(seed * 31);
            for (int step = 0; step < STEPS; step++) {
                randomCommands(sim, random);
                int[][] before = positions(sim.world);
                sim.step(1);
                checkInvariants(sim.world, before, "seed " + seed + " step " + sim.world.step());
                for (int i = 0; i < sim.world.robotCount(); i++) {
                    Robot r = sim.world.robot(i);
                    carrySteps += r.carried() >= 0 ? 1 : 0;
                    doorways += map.terrain(r.x(), r.y()) == Terrain.DOOR ? 1 : 0;
                }
            }
            nearMisses += sim.world.nearMisses();
        }
        // the random orders really exercise the rules checked above
        assertThat(carrySteps).isGreaterThan(1000);
        assertThat(nearMisses).isGreaterThan(100);
        assertThat(doorways).isGreaterThan(100);
    }

    @Test
    void sameSeedAndCommandsGiveTheSameWorld() throws Exception {
        String a = run(7);
        assertThat(run(7)).isEqualTo(a);
        assertThat(run(8)).isNotEqualTo(a);
    }

    private static String run(long seed) throws Exception {
        WarehouseMap map = MapGenerator.generate(24, 18, 16, 30, 2, 1);
        Sim sim = new Sim(map, SimRules.DEFAULT.withSeed(seed));
        Random random = new Random(1);
        for (int step = 0; step < 200; step++) {
            randomCommands(sim, random);
            sim.step(1);
        }
        return new String(eu.brain.iot.robotsim.view.Json.bytes(
                eu.brain.iot.robotsim.view.WorldDocument.world(sim.world, 500, eu.brain.iot.robotsim.view.CommandCounts.NONE)), java.nio.charset.StandardCharsets.UTF_8);
    }

    private static void randomCommands(Sim sim, Random random) throws CommandRejectedException {
        World w = sim.world;
        WarehouseMap map = w.map();
        for (int i = 0; i < w.robotCount(); i++) {
            int dice = random.nextInt(100);
            if (dice < 8) {
                int x = random.nextInt(map.width());
                int y = random.nextInt(map.height());
                if (map.terrain(x, y).passable()) {
                    sim.commands.goTo(i, x, y);
                }
            } else if (dice < 11) {
                sim.commands.pick(i);
            } else if (dice < 14) {
                sim.commands.place(i);
            } else if (dice < 16) {
                sim.commands.cancel(i, MissionType.values()[random.nextInt(3)], null);
            }
        }
        for (int d = 0; d < w.doorCount(); d++) {
            if (random.nextInt(10) == 0) {
                sim.commands.door(d, random.nextBoolean());
            }
        }
    }

    private static int[][] positions(World w) {
        int[][] p = new int[w.robotCount()][];
        for (int i = 0; i < w.robotCount(); i++) {
            p[i] = new int[] {w.robot(i).x(), w.robot(i).y()};
        }
        return p;
    }

    private static void checkInvariants(World w, int[][] before, String where) {
        WarehouseMap map = w.map();
        Set<Integer> occupied = new HashSet<>();
        for (int i = 0; i < w.robotCount(); i++) {
            Robot r = w.robot(i);
            int cell = r.y() * map.width() + r.x();
            assertThat(occupied.add(cell)).as("%s: two robots on (%d,%d)", where, r.x(), r.y()).isTrue();
            assertThat(w.robotAt(r.x(), r.y())).as(where).isEqualTo(i);
            assertThat(map.terrain(r.x(), r.y()).passable()).as(where).isTrue();
            int moved = Math.abs(r.x() - before[i][0]) + Math.abs(r.y() - before[i][1]);
            assertThat(moved).as("%s: %s moved %d cells", where, r.id(), moved).isLessThanOrEqualTo(1);
            if (moved == 1 && map.terrain(r.x(), r.y()) == Terrain.DOOR) {
                int door = -1;
                for (int d = 0; d < w.doorCount(); d++) {
                    if (w.door(d).x() == r.x() && w.door(d).y() == r.y()) {
                        door = d;
                    }
                }
                assertThat(w.door(door).state()).as("%s: entered a door that was not open", where)
                        .isIn(DoorState.OPEN, DoorState.CLOSING);
            }
            if (r.carried() >= 0) {
                Cart c = w.cart(r.carried());
                assertThat(c.carriedBy()).as(where).isEqualTo(i);
                assertThat(c.x()).as(where).isEqualTo(r.x());
                assertThat(c.y()).as(where).isEqualTo(r.y());
            }
        }
        assertThat(w.cartCount()).isEqualTo(map.carts().size());
        Set<Integer> cartCells = new HashSet<>();
        for (int c = 0; c < w.cartCount(); c++) {
            Cart cart = w.cart(c);
            if (cart.carriedBy() >= 0) {
                assertThat(w.robot(cart.carriedBy()).carried()).as("%s: %s", where, cart.id()).isEqualTo(c);
            } else {
                assertThat(cartCells.add(cart.y() * map.width() + cart.x()))
                        .as("%s: two carts on one cell", where).isTrue();
                assertThat(w.cartAt(cart.x(), cart.y())).as("%s: %s not where the floor says", where, cart.id())
                        .isEqualTo(c);
            }
        }
        int floorCarts = 0;
        for (int y = 0; y < map.height(); y++) {
            for (int x = 0; x < map.width(); x++) {
                floorCarts += w.cartAt(x, y) >= 0 ? 1 : 0;
            }
        }
        assertThat(floorCarts).as("%s: floor cart count", where).isEqualTo(cartCells.size());
    }
}
