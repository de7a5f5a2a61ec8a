package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.node.ObjectNode;

class TrafficFiguresTest {

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
        assertThat(f.path("trafficPlanningMsPerRound").asDouble()).isEqualTo(3.5);
        ObjectNode none = ReportWriter.MAPPER.createObjectNode();
        TrafficFigures.put(none, dir.resolve("missing.log"));
        assertThat(none.path("goTosSent").isNull()).isTrue();
    }

    @Test
    void everyInstanceThatDroveTheFleetCountsInEveryNodesLogs(@TempDir Path dir) throws Exception {
        // node1's instance drove, its behaviour was restarted (counts from zero again), then node1 was killed
        Path node1 = dir.resolve("node1.log");
        Files.writeString(node1, """
                traffic: 10 rounds, planning 2.00 ms per round, 20 go-tos sent, 20 along reserved paths, 0 robots \
                held, 1 legs cancelled
                traffic: 50 rounds, planning 2.00 ms per round, 100 go-tos sent, 90 along reserved paths, 0 robots \
                held, 2 legs cancelled
                traffic: 5 rounds, planning 4.00 ms per round, 10 go-tos sent, 10 along reserved paths, 0 robots \
                held, 0 legs cancelled
                """);
        Path node2 = dir.resolve("node2.log"); // stood by: no line
        Files.writeString(node2, "robot fleet: the instance on node node1 drives the fleet; this one stands by\n");
        Path node3 = dir.resolve("node3.log"); // took over when node1 died
        Files.writeString(node3, """
                traffic: 45 rounds, planning 1.00 ms per round, 70 go-tos sent, 70 along reserved paths, 0 robots \
                held, 3 legs cancelled
                """);
        ObjectNode f = ReportWriter.MAPPER.createObjectNode();
        TrafficFigures.put(f, List.of(node1, node2, node3));
        assertThat(f.path("goTosSent").asLong()).isEqualTo(100 + 10 + 70);
        assertThat(f.path("goTosAlongReservedPaths").asLong()).isEqualTo(90 + 10 + 70);
        assertThat(f.path("trafficLegsCancelled").asLong()).isEqualTo(2 + 0 + 3);
        assertThat(f.path("trafficPlanningMsPerRound").asDouble()).isEqualTo((50 * 2.0 + 5 * 4.0 + 45 * 1.0) / 100);
    }
}
