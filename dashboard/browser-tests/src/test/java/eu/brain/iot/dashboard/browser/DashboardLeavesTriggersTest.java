package eu.brain.iot.dashboard.browser;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * The BMS installs a behaviour only for events that no installed consumer takes, so the dashboard must take none of
 * the behaviours' triggers. Checked twice on the real node (no browser needed): every behaviour of the project's
 * repository keeps event types that the dashboard's consumer (the snapshot's {@code consumed}) does not take, and the
 * dashboard takes none of the triggers the behaviours are designed around (the edge's position and door events, the
 * orchestrator's rendezvous offers); and with the dashboard running, the robot behaviour is installed on demand when
 * its first event comes, and the dashboard shows it among the installed behaviours. Sharing other types (a command's
 * outcome, an obstacle) is fine: the BMS needs one type per behaviour that nobody else takes.
 */
class DashboardLeavesTriggersTest {

    private static final String ROBOT_TRIGGER = "eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation";
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path home;

    @Test
    void aNodeWithTheDashboardStillInstallsTheRobotBehaviourOnDemand() throws Exception {
        List<List<String>> behaviourTypes = behaviourConsumedTypes();
        assertThat(behaviourTypes).anySatisfy(types -> assertThat(types).contains(ROBOT_TRIGGER));
        try (RobotSim sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
                Node node = new Node(home.resolve("node"), sim.baseUri(), 500, true).withShell().start()) {
            List<String> consumed = new ArrayList<>();
            snapshot(node).get("consumed").forEach(t -> consumed.add(t.asText()));
            assertThat(consumed).isNotEmpty().doesNotContain(ROBOT_TRIGGER,
                    "eu.brain.iot.edge.api.RobotPositionChanged", "eu.brain.iot.edge.api.DoorStateChanged",
                    "eu.brain.iot.edge.api.RobotEvent", "eu.brain.iot.behaviours.events.ConnectorResolveCollisionOffer");
            for (List<String> types : behaviourTypes) {
                assertThat(types).as("a behaviour's consumed types, not all taken by the dashboard")
                        .isNotEmpty().anySatisfy(t -> assertThat(consumed).doesNotContain(t));
            }

            node.type("bus:publish " + ROBOT_TRIGGER);
            await("the robot behaviour installed, as the dashboard shows it").atMost(Duration.ofSeconds(60))
                    .pollInterval(Duration.ofMillis(250)).until(() -> {
                        JsonNode behaviours = snapshot(node).get("fabric").get("behaviours");
                        return behaviours != null && behaviours.toString().contains("eu.brain.iot.behaviours.robot");
                    });
        }
    }

    /** The event types each behaviour of the project's repository consumes (its index's behaviour capabilities). */
    private static List<List<String>> behaviourConsumedTypes() throws Exception {
        String index = Files.readString(Node.ROOT.resolve("repository/target/repository/index.xml"));
        Matcher m = Pattern.compile("<capability namespace=\"eu.brain.iot.behaviour\">\\s*<attribute name=\"consumed\""
                + " value=\"([^\"]*)\"").matcher(index);
        List<List<String>> types = new ArrayList<>();
        while (m.find()) {
            types.add(List.of(m.group(1).split(",")));
        }
        return types;
    }

    private static JsonNode snapshot(Node node) throws Exception {
        HttpResponse<String> r = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                node.base().resolve("dashboard/api/snapshot")).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        return JSON.readTree(r.body());
    }
}
