package eu.brain.iot.robotsim.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class MapParserTest {

    @Test
    void paperWarehouseHasThreeRobotsThreeCartsAndOneDoor() {
        WarehouseMap map = WarehouseMap.paper();
        assertThat(map.robots()).extracting(Placement::id).containsExactly("robot1", "robot2", "robot3");
        assertThat(map.carts()).extracting(Placement::id).containsExactly("cart1", "cart2", "cart3");
        assertThat(map.doors()).extracting(Placement::id).containsExactly("door1");
        Placement door = map.doors().get(0);
        assertThat(map.terrain(door.x(), door.y())).isEqualTo(Terrain.DOOR);
        for (Placement r : map.robots()) {
            assertThat(map.terrain(r.x(), r.y()).area()).isEqualTo(1);
        }
        for (Placement c : map.carts()) {
            assertThat(map.terrain(c.x(), c.y()).area()).isEqualTo(2);
        }
        assertThat(map.terrainRows()).anyMatch(row -> row.contains("s"));
    }

    @Test
    void textRoundTrips() throws Exception {
        WarehouseMap map = WarehouseMap.paper();
        WarehouseMap again = MapParser.parse("again", map.toText());
        assertThat(again.terrainRows()).isEqualTo(map.terrainRows());
        assertThat(again.robots()).isEqualTo(map.robots());
        assertThat(again.carts()).isEqualTo(map.carts());
        assertThat(again.doors()).isEqualTo(map.doors());
        assertThat(again.doorOpenSteps()).isEqualTo(map.doorOpenSteps());
    }

    @Test
    void headersAreRead() throws Exception {
        WarehouseMap map = MapParser.parse("t", "# hello\nname: small\ndoor-open-steps: 7\nmap:\n#D#\n#R#\n");
        assertThat(map.name()).isEqualTo("small");
        assertThat(map.doorOpenSteps()).isEqualTo(7);
        assertThat(map.width()).isEqualTo(3);
        assertThat(map.height()).isEqualTo(2);
    }

    @Test
    void unknownCellIsReportedWithLineAndColumn() {
        assertThatThrownBy(() -> MapParser.parse("w.map", "name: x\nmap:\n###\n#x#\n"))
                .isInstanceOf(MapFormatException.class)
                .hasMessage("w.map:4:2: unknown cell 'x' (expected one of # . d u s D R C)");
    }

    @Test
    void raggedRowIsReported() {
        assertThatThrownBy(() -> MapParser.parse("w.map", "map:\n###\n##\n"))
                .hasMessageStartingWith("w.map:3:3: row has 2 cells but the first row has 3");
    }

    @Test
    void missingGridAndBadHeadersAreReported() {
        assertThatThrownBy(() -> MapParser.parse("w.map", "name: x\n"))
                .hasMessageContaining("no 'map:' line");
        assertThatThrownBy(() -> MapParser.parse("w.map", "colour: red\nmap:\n#\n"))
                .hasMessage("w.map:1:1: unknown header 'colour' (known: name, door-open-steps)");
        assertThatThrownBy(() -> MapParser.parse("w.map", "door-open-steps: soon\nmap:\n#\n"))
                .hasMessageStartingWith("w.map:1:17: door-open-steps must be a whole number");
        assertThatThrownBy(() -> MapParser.parse("w.map", "map:\n\n"))
                .hasMessageContaining("the grid after 'map:' is empty");
    }
}
