package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The report's per-node section and the summary's line per node. */
class NodeReportTest {
    private static final NodeReport LIVE = new NodeReport("node1", null, null, List.of("door1", "robot1", "robot3"),
            List.of("eu.brain.iot.behaviours.door", "eu.brain.iot.behaviours.robot"), Map.of("node2", 120L),
            Map.of("node2", 80L), 6_000L, 20_000);
    private static final NodeReport KILLED = new NodeReport("node2", 20_000L, null, List.of("robot2"), List.of(),
            Map.of("node1", 80L), Map.of("node1", 120L), 1_500L, 5_000);
    private static final NodeReport UNKNOWN = new NodeReport("node3", null, null, null, null, null, null, null, 20_000);

    private static final NodeReport RESTARTED = new NodeReport("node2", 20_000L, 50_000L, List.of("robot2"),
            List.of(), Map.of("node1", 80L), Map.of("node1", 120L), 1_500L, 5_000);

    private static ArrayNode section(NodeReport... nodes) {
        ArrayNode array = ReportWriter.MAPPER.createArrayNode();
        ReportWriter.nodes(array, List.of(nodes));
        return array;
    }

    @Test
    void eachNodeHasItsFigures() {
        JsonNode n = section(LIVE).get(0);
        assertThat(n.path("name").asText()).isEqualTo("node1");
        assertThat(n.get("killedAtWarehouseSeconds").isNull()).isTrue();
        assertThat(n.path("devicesOwned")).extracting(JsonNode::asText).containsExactly("door1", "robot1", "robot3");
        assertThat(n.path("behavioursInstalled")).extracting(JsonNode::asText)
                .containsExactly("eu.brain.iot.behaviours.door", "eu.brain.iot.behaviours.robot");
        assertThat(n.path("eventsSentTo").path("node2").asLong()).isEqualTo(120);
        assertThat(n.path("eventsReceivedFrom").path("node2").asLong()).isEqualTo(80);
        assertThat(n.path("cpuSeconds").asDouble()).isEqualTo(6.0);
        assertThat(n.path("cpuPercentOfOneCore").asDouble()).as("6 s over 20 s").isEqualTo(30.0);
    }

    @Test
    void aKilledNodeHasItsTimeOfDeathAndItsLastReading() {
        JsonNode n = section(LIVE, KILLED).get(1);
        assertThat(n.path("killedAtWarehouseSeconds").asDouble()).isEqualTo(20.0);
        assertThat(n.path("devicesOwned")).extracting(JsonNode::asText).containsExactly("robot2");
        assertThat(n.path("behavioursInstalled")).isEmpty();
        assertThat(n.path("cpuPercentOfOneCore").asDouble()).as("1.5 s over the 5 s it ran").isEqualTo(30.0);
    }

    @Test
    void aNodeStartedAgainHasBothTimes() {
        JsonNode n = section(RESTARTED).get(0);
        assertThat(n.path("killedAtWarehouseSeconds").asDouble()).isEqualTo(20.0);
        assertThat(n.path("restartedAtWarehouseSeconds").asDouble()).isEqualTo(50.0);
        assertThat(Summary.nodeLine(RESTARTED)).startsWith("node2 killed at 20.0 s, started again at 50.0 s: owns "
                + "robot2;");
    }

    @Test
    void unknownFiguresAreNull() {
        JsonNode n = section(UNKNOWN).get(0);
        for (String field : List.of("killedAtWarehouseSeconds", "restartedAtWarehouseSeconds", "devicesOwned", "behavioursInstalled", "eventsSentTo",
                "eventsReceivedFrom", "cpuSeconds", "cpuPercentOfOneCore")) {
            assertThat(n.has(field)).as(field).isTrue();
            assertThat(n.get(field).isNull()).as(field).isTrue();
        }
    }

    @Test
    void theSummaryHasALinePerNode() {
        assertThat(Summary.nodeLine(LIVE)).isEqualTo("node1: owns door1, robot1, robot3; behaviours door, robot; "
                + "sent node2 120; received node2 80; CPU 6.0 s (30% of one core)");
        assertThat(Summary.nodeLine(KILLED)).isEqualTo("node2 killed at 20.0 s: owns robot2; behaviours none; "
                + "sent node1 80; received node1 120; CPU 1.5 s (30% of one core)");
        assertThat(Summary.nodeLine(UNKNOWN)).isEqualTo("node3: owns ?; behaviours ?; sent ?; received ?; CPU ?");
    }
}
