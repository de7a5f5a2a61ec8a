package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;

class FleetBoundTest {

    @Test
    void oneRobotOneCartOneStorageCellInALine() throws Exception {
        // dock (1,1), cart (4,1), storage (2,1): 3 steps to the cart, 2 back to storage, 1 home, 2 + 2 to lift and
        // place = 10 steps of 0.5 s: 720 carts per hour for one robot
        JsonNode doc = ReportWriter.MAPPER.readTree("""
                {"map": ["######", "#.s..#", "######"],
                 "robots": [{"x": 1, "y": 1}], "carts": [{"x": 4, "y": 1}]}""");
        assertThat(FleetBound.cartsPerHour(doc, 500)).isEqualTo(720.0);
    }
}
