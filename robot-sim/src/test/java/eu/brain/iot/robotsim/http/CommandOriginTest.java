package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.view.CommandOrigins;
import java.net.http.HttpRequest;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Which node commanded each robot: the X-Brain-Node header over real HTTP, and the log of hand-overs. */
class CommandOriginTest {
    private static final String GOTO = "robot_local_control/NavigationComponent/GoToComponent/add";
    private RobotSim sim;
    private Client client;

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        client = new Client(sim.baseUri());
    }

    @AfterEach
    void stop() {
        sim.close();
    }

    private Client.Answer goTo(String robot, String node) throws Exception {
        HttpRequest.Builder b = HttpRequest.newBuilder(sim.baseUri().resolve(robot + "/" + GOTO))
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(
                        "{\"x\":2,\"y\":4}"));
        if (node != null) {
            b.header(CommanderHeader.NAME, node);
        }
        return client.send(b);
    }

    @Test
    void theLastCommandingNodeIsRecordedPerRobotWithItsTimes() throws Exception {
        long before = System.currentTimeMillis();
        sim.step(4); // warehouse time 2 s
        assertThat(goTo("robot1", "node2").status()).isEqualTo(200);
        JsonNode robot1 = client.get("world").json().path("commandOrigins").path("robots").path("robot1");
        assertThat(robot1.path("node").asText()).isEqualTo("node2");
        assertThat(robot1.path("warehouseMs").asLong()).isEqualTo(2_000);
        assertThat(robot1.path("wallMillis").asLong()).isBetween(before, System.currentTimeMillis());
        assertThat(robot1.path("commands").asLong()).isEqualTo(1);
        assertThat(robot1.path("handovers").asLong()).isZero();
        assertThat(robot1.path("closestHandover").isNull()).isTrue();
        assertThat(client.get("world").json().path("commandOrigins").path("robots").has("robot2"))
                .as("a robot never commanded").isFalse();
    }

    @Test
    void aCommandWithoutTheHeaderIsFromUnknown() throws Exception {
        assertThat(goTo("robot2", null).status()).isEqualTo(200);
        assertThat(sim.commandOrigins().robots().get("robot2").node()).isEqualTo(CommanderHeader.UNKNOWN);
    }

    @Test
    void aCommandFromAnotherNodeIsLoggedAsAHandOver() throws Exception {
        goTo("robot3", "node1");
        goTo("robot3", "node1");
        sim.step(2);
        goTo("robot3", "node2");
        CommandOrigins origins = sim.commandOrigins();
        assertThat(origins.robots().get("robot3").handovers()).isEqualTo(1);
        assertThat(origins.robots().get("robot3").commands()).isEqualTo(3);
        assertThat(origins.changes()).singleElement().satisfies(c -> {
            assertThat(c.robot()).isEqualTo("robot3");
            assertThat(c.from()).isEqualTo("node1");
            assertThat(c.to()).isEqualTo("node2");
            assertThat(c.fromLastWarehouseMs()).isZero();
            assertThat(c.warehouseMs()).isEqualTo(1_000);
            assertThat(c.gapWallMillis()).isNotNegative();
        });
        assertThat(origins.robots().get("robot3").closestHandover()).isEqualTo(origins.changes().get(0));
        JsonNode change = client.get("world").json().path("commandOrigins").path("changes").path(0);
        assertThat(change.path("from").asText() + ">" + change.path("to").asText()).isEqualTo("node1>node2");
    }

    @Test
    void cancelsCountRefusedCommandsDoNot() throws Exception {
        Client.Answer refused = client.send(HttpRequest.newBuilder(sim.baseUri().resolve(
                "robot1/" + GOTO)).header(CommanderHeader.NAME, "node3").header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString("{\"x\":0,\"y\":0}")));
        assertThat(refused.status()).as(refused.body()).isEqualTo(422);
        client.send(HttpRequest.newBuilder(sim.baseUri().resolve(
                "robot1/robot_local_control/NavigationComponent/GoToComponent/cancel"))
                .header(CommanderHeader.NAME, "node4").header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString("{}")));
        assertThat(sim.commandOrigins().changes()).as("node3's command was refused: it drove nothing").isEmpty();
        assertThat(sim.commandOrigins().robots().get("robot1").node()).isEqualTo("node4");
    }

    @Test
    void pollsAreNoCommands() throws Exception {
        client.send(HttpRequest.newBuilder(sim.baseUri().resolve("robot1/robot_local_control/state"))
                .header(CommanderHeader.NAME, "node9").GET());
        assertThat(sim.commandOrigins().robots()).isEmpty();
    }

    @Test
    void aHeaderThatNamesNoNodeIsRefusedWithAJsonError() throws Exception {
        Client.Answer a = goTo("robot1", "node 2; drop");
        assertThat(a.status()).isEqualTo(400);
        assertThat(a.json().path("field").asText()).isEqualTo(CommanderHeader.NAME);
        assertThat(a.json().path("error").asText()).contains("X-Brain-Node").contains("node 2; drop");
        assertThat(sim.robot("robot1").mission()).as("nothing done").isNull();
        assertThat(sim.commandOrigins().robots()).isEmpty();
    }

    @Test
    void theLogIsBoundedAndCountsWhatItDropped() {
        AtomicLong wall = new AtomicLong(1_000);
        CommandOriginLog log = new CommandOriginLog(() -> 0, wall::get, 2);
        for (int i = 0; i < 5; i++) {
            wall.addAndGet(10 * (5 - i));
            log.record("robot1", "node" + (i % 2 + 1));
        }
        CommandOrigins s = log.snapshot();
        assertThat(s.changes()).hasSize(2);
        assertThat(s.changesDropped()).isEqualTo(2);
        assertThat(s.robots().get("robot1").handovers()).isEqualTo(4);
        // the shortest gap (the last: 10 ms) is kept per robot whatever the log dropped
        assertThat(s.robots().get("robot1").closestHandover().gapWallMillis()).isEqualTo(10);
    }
}
