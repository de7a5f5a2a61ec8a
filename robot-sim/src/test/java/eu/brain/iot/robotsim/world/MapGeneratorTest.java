package eu.brain.iot.robotsim.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class MapGeneratorTest {

    @Test
    void largeWarehouseHasWhatWasAsked() {
        WarehouseMap map = MapGenerator.generate(200, 100, 1000, 2000, 5, 1);
        assertThat(map.width()).isEqualTo(200);
        assertThat(map.height()).isEqualTo(100);
        assertThat(map.robots()).hasSize(1000);
        assertThat(map.carts()).hasSize(2000);
        assertThat(map.doors()).hasSize(5);
        assertThat(map.terrainRows()).anyMatch(r -> r.contains("s"));
    }

    @Test
    void theScenariosLargerWarehouseHasOneDoorSoEveryTripCrossesIt() {
        WarehouseMap map = MapGenerator.generate(60, 30, 30, 60, 1, 1);
        assertThat(map.robots()).hasSize(30);
        assertThat(map.carts()).hasSize(60);
        assertThat(map.doors()).hasSize(1);
        long openings = map.terrainRows().stream().filter(r -> r.matches("#+D#+")).count();
        assertThat(openings).as("the unload area is reached only through the door's wall row").isEqualTo(1);
    }

    @Test
    void tenThousandRobotsFit() {
        WarehouseMap map = MapGenerator.generate(400, 150, 10_000, 2000, 10, 1);
        assertThat(map.robots()).hasSize(10_000);
    }

    @Test
    void seedDecidesTheCartsAndNothingElse() {
        String a = MapGenerator.text("n", 60, 30, 20, 50, 2, 1);
        assertThat(MapGenerator.text("n", 60, 30, 20, 50, 2, 1)).isEqualTo(a);
        assertThat(MapGenerator.text("n", 60, 30, 20, 50, 2, 2)).isNotEqualTo(a);
    }

    @Test
    void everyRobotCanReachTheUnloadAreaAndEveryCartTouchesAnAisle() {
        WarehouseMap map = MapGenerator.generate(40, 30, 30, 60, 2, 3);
        World world = new World(map, SimRules.DEFAULT);
        int[] noCarts = new int[map.width() * map.height()];
        java.util.Arrays.fill(noCarts, -1);
        Placement target = map.carts().get(0);
        for (Placement r : map.robots()) {
            assertThat(world.planner.plan(world.cell(r.x(), r.y()), world.cell(target.x(), target.y()),
                    noCarts, false)).as(r.id()).isNotNull();
        }
        for (Placement c : map.carts()) {
            boolean aisle = false;
            for (Heading h : Heading.values()) {
                int x = c.x() + h.dx();
                int y = c.y() + h.dy();
                aisle |= map.inside(x, y) && map.terrain(x, y).passable() && world.cartAt(x, y) < 0;
            }
            assertThat(aisle).as(c.id()).isTrue();
        }
    }

    @Test
    void tooManyCartsOrRobotsAreExplained() {
        assertThatThrownBy(() -> MapGenerator.text("n", 20, 20, 5, 10_000, 1, 1))
                .hasMessageContaining("carts do not fit");
        assertThatThrownBy(() -> MapGenerator.text("n", 20, 20, 10_000, 0, 1, 1))
                .hasMessageContaining("make the map taller");
    }
}
