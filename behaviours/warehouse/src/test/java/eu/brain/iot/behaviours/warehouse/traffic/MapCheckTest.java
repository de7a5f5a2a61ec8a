package eu.brain.iot.behaviours.warehouse.traffic;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class MapCheckTest {

    @Test
    void theGeneratorsKindOfWarehouseIsAccepted() {
        assertThat(MapCheck.refusal(TrafficMap.parse(FleetPlannerTest.SMALL), 12)).isEmpty();
    }

    @Test
    void aLongSingleLaneIsRefusedWithItsLengthAndTheWindow() {
        String rows = String.join("\n",
                "##########################",
                "#...#####################.#".substring(0, 26),
                "#........................#",
                "##########################");
        assertThat(MapCheck.refusal(TrafficMap.parse(rows), 12)).hasValueSatisfying(why -> assertThat(why)
                .contains("one-cell passage").contains("planning window (12 steps)"));
    }

    @Test
    void aMapInTwoPartsIsRefused() {
        String rows = String.join("\n",
                "#######",
                "#..#..#",
                "#..#..#",
                "#######");
        assertThat(MapCheck.refusal(TrafficMap.parse(rows), 12)).hasValueSatisfying(why -> assertThat(why)
                .contains("cannot be reached"));
    }

    @Test
    void aDoorInACornerIsRefused() {
        String rows = String.join("\n",
                "######",
                "#....#",
                "#....#",
                "#D####",
                "#.####",
                "######");
        String corner = rows.replace("#D####\n#.####", "#.D###\n####.#".substring(0, 6) + "\n#.####");
        assertThat(MapCheck.refusal(TrafficMap.parse(rows), 12)).isEmpty();
        assertThat(corner).isNotNull();
        String bad = String.join("\n",
                "######",
                "#....#",
                "#...D#",
                "####.#",
                "######");
        assertThat(MapCheck.refusal(TrafficMap.parse(bad), 12)).hasValueSatisfying(why -> assertThat(why)
                .contains("door at (4,2)"));
    }
}
