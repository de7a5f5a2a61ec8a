package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

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

    @Test
    void theTrafficLineOfTheNodeLogBecomesFigures(@TempDir Path dir) throws Exception {
        Path log = dir.resolve("node.log");
        Files.writeString(log, """
                01:00:28 INFO RobotFleet - traffic: 1 rounds, planning 17.02 ms per round, 0 go-tos sent, 0 along \
                reserved paths, 0 robots held, 0 legs cancelled
                01:00:48 INFO RobotFleet - traffic: 90 rounds, planning 3.50 ms per round, 40 go-tos sent, 38 along \
                reserved paths, 2 robots held, 1 legs cancelled
                """);
        ObjectNode f = ReportWriter.MAPPER.createObjectNode();
        TrafficFigures.put(f, log);
        assertThat(f.path("goTosSent").asLong()).isEqualTo(40);
        assertThat(f.path("goTosAlongReservedPaths").asLong()).isEqualTo(38);
        assertThat(f.path("trafficLegsCancelled").asLong()).isEqualTo(1);
        ObjectNode none = ReportWriter.MAPPER.createObjectNode();
        TrafficFigures.put(none, dir.resolve("missing.log"));
        assertThat(none.path("goTosSent").isNull()).isTrue();
    }
}
