package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The REST API over real HTTP against the paper's warehouse, stepped by hand. */
class RestContractTest {
    private static final String R3 = "robot3/robot_local_control/";
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

    @Test
    void serverBindsLoopbackOnAnEphemeralPort() {
        assertThat(sim.baseUri().getHost()).isEqualTo("127.0.0.1");
        assertThat(sim.port()).isPositive();
    }

    @Test
    void stateAnswerHasTheDocumentedShape() throws Exception {
        Client.Answer a = client.get("robot1/robot_local_control/state");
        assertThat(a.status()).isEqualTo(200);
        assertThat(a.body()).isEqualTo("{\"id\":\"robot1\",\"x\":2,\"y\":1,\"heading\":\"N\",\"area\":1,"
                + "\"state\":\"stopped\",\"detect\":0,\"cart\":null,\"mission\":null,\"nearMisses\":0,\"deadlocks\":0,"
                + "\"waitSteps\":0,\"longestWaitSteps\":0}");
    }

    @Test
    void goToIsQueuedThenRunsThenFinishes() throws Exception {
        Client.Answer added = client.post(R3 + "NavigationComponent/GoToComponent/add", "{\"x\":6,\"y\":4}");
        assertThat(added.status()).isEqualTo(200);
        JsonNode mission = added.json().get("mission");
        assertThat(mission.get("state").asText()).isEqualTo("queued");
        assertThat(mission.get("type").asText()).isEqualTo("goto");
        assertThat(mission.get("goal").get("y").asInt()).isEqualTo(4);
        long id = mission.get("id").asLong();
        assertThat(client.get(R3 + "state").json().get("mission").get("state").asText()).isEqualTo("queued");

        sim.step(1);
        JsonNode s = client.get(R3 + "state").json();
        assertThat(s.get("state").asText()).isEqualTo("running");
        assertThat(s.get("y").asInt()).isEqualTo(2);
        assertThat(s.get("heading").asText()).isEqualTo("S");
        assertThat(s.get("mission").get("id").asLong()).isEqualTo(id);
        assertThat(s.get("mission").get("state").asText()).isEqualTo("running");

        assertThat(client.post("admin/step", "{\"steps\":2}").json().get("step").asLong()).isEqualTo(3);
        s = client.get(R3 + "state").json();
        assertThat(s.get("y").asInt()).isEqualTo(4);
        assertThat(s.get("area").asInt()).isZero();
        assertThat(s.get("state").asText()).isEqualTo("stopped");
        assertThat(s.get("mission").get("state").asText()).isEqualTo("finished");

        JsonNode q = client.get(R3 + "NavigationComponent/GoToComponent/query_state").json();
        assertThat(q.get("current").isNull()).isTrue();
        assertThat(q.get("history").get(0).get("id").asLong()).isEqualTo(id);
        assertThat(client.post(R3 + "NavigationComponent/GoToComponent/query_state", "").status()).isEqualTo(200);
    }

    @Test
    void pickCarryAndPlaceOverRest() throws Exception {
        // cart3 stands at (16,7) behind the door at (9,5)
        assertThat(client.post("door1/door_controller/command", "{\"data\":1.0}").json().get("state").asText())
                .isEqualTo("opening");
        client.post(R3 + "NavigationComponent/GoToComponent/add", "{\"x\":16,\"y\":7}");
        assertThat(client.post(R3 + "NavigationComponent/PickComponent/add", "").status()).isEqualTo(200);
        client.post(R3 + "NavigationComponent/GoToComponent/add", "{\"x\":13,\"y\":2}");
        assertThat(client.post(R3 + "PlaceComponent/add", "{}").status()).as("alias without NavigationComponent")
                .isEqualTo(200);
        sim.step(60);
        JsonNode s = client.get(R3 + "state").json();
        assertThat(s.get("x").asInt()).isEqualTo(13);
        assertThat(s.get("y").asInt()).isEqualTo(2);
        assertThat(s.get("area").asInt()).isEqualTo(3);
        assertThat(s.get("cart").isNull()).isTrue();
        assertThat(s.get("mission").get("type").asText()).isEqualTo("place");
        assertThat(s.get("mission").get("state").asText()).isEqualTo("finished");
        JsonNode carts = client.get("world").json().get("carts");
        assertThat(carts.get(2).get("id").asText()).isEqualTo("cart3");
        assertThat(carts.get(2).get("x").asInt()).isEqualTo(13);
        assertThat(carts.get(2).get("y").asInt()).isEqualTo(2);
        assertThat(carts.get(2).get("carriedBy").isNull()).isTrue();
    }

    @Test
    void cartIsReportedWhileCarried() throws Exception {
        client.post("door1/door_controller/command", "{\"data\":1}");
        client.post(R3 + "NavigationComponent/GoToComponent/add", "{\"x\":10,\"y\":7}");
        client.post(R3 + "NavigationComponent/PickComponent/add", "");
        sim.step(30);
        assertThat(client.get(R3 + "state").json().get("cart").asText()).isEqualTo("cart2");
        JsonNode cart2 = client.get("world").json().get("carts").get(1);
        assertThat(cart2.get("carriedBy").asText()).isEqualTo("robot3");
    }

    @Test
    void cancelAndQueryState() throws Exception {
        long first = client.post(R3 + "NavigationComponent/GoToComponent/add", "{\"x\":6,\"y\":4}")
                .json().get("mission").get("id").asLong();
        long second = client.post(R3 + "NavigationComponent/GoToComponent/add", "{\"x\":8,\"y\":4}")
                .json().get("mission").get("id").asLong();
        sim.step(1);
        JsonNode q = client.get(R3 + "NavigationComponent/GoToComponent/query_state").json();
        assertThat(q.get("current").get("id").asLong()).isEqualTo(first);
        assertThat(q.get("queued").get(0).get("id").asLong()).isEqualTo(second);

        JsonNode c = client.post(R3 + "NavigationComponent/GoToComponent/cancel", "{\"id\":" + second + "}").json();
        assertThat(c.get("cancelled").get(0).get("state").asText()).isEqualTo("failed");
        assertThat(c.get("cancelled").get(0).get("reason").asText()).isEqualTo("cancelled");
        c = client.post(R3 + "NavigationComponent/GoToComponent/cancel", "").json();
        assertThat(c.get("cancelled").get(0).get("id").asLong()).isEqualTo(first);
        sim.step(3);
        JsonNode s = client.get(R3 + "state").json();
        assertThat(s.get("y").asInt()).isEqualTo(2);
        assertThat(s.get("mission").get("state").asText()).isEqualTo("failed");
        Client.Answer none = client.post(R3 + "NavigationComponent/GoToComponent/cancel", "{\"id\":999}");
        assertThat(none.status()).isEqualTo(404);
        assertThat(none.json().get("field").asText()).isEqualTo("id");
    }

    @Test
    void doorOpensOverTimeAndCloses() throws Exception {
        assertThat(client.get("door1/door_controller/state").body()).isEqualTo(
                "{\"id\":\"door1\",\"x\":9,\"y\":5,\"state\":\"closed\",\"data\":0.0,\"stepsLeft\":0}");
        client.post("door1/door_controller/command", "{\"data\":1.0}");
        sim.step(3);
        assertThat(client.get("door1/door_controller/state").json().get("stepsLeft").asInt()).isEqualTo(1);
        sim.step(1);
        JsonNode open = client.get("door1/door_controller/state").json();
        assertThat(open.get("state").asText()).isEqualTo("open");
        assertThat(open.get("data").asDouble()).isEqualTo(1.0);
        assertThat(client.post("door1/door_controller/command", "{\"data\":0.0}").json().get("state").asText())
                .isEqualTo("closed");
    }

    @Test
    void robotStopsBeforeTheDoorWithDetect2() throws Exception {
        client.post(R3 + "NavigationComponent/GoToComponent/add", "{\"x\":9,\"y\":7}");
        sim.step(12);
        JsonNode s = client.get(R3 + "state").json();
        assertThat(s.get("x").asInt()).isEqualTo(9);
        assertThat(s.get("y").asInt()).isEqualTo(4);
        assertThat(s.get("state").asText()).isEqualTo("stopped");
        assertThat(s.get("detect").asInt()).isEqualTo(2);
    }

    @Test
    void worldEndpointHasMapCartsDoorsAndCounters() throws Exception {
        JsonNode w = client.get("world").json();
        assertThat(w.get("width").asInt()).isEqualTo(20);
        assertThat(w.get("map")).hasSize(10);
        assertThat(w.get("map").get(5).asText()).isEqualTo("#########D##########");
        assertThat(w.get("robots")).hasSize(3);
        assertThat(w.get("carts")).hasSize(3);
        assertThat(w.get("doors").get(0).get("id").asText()).isEqualTo("door1");
        assertThat(w.get("counters").get("nearMisses").asLong()).isZero();
        assertThat(w.get("counters").get("perRobot").get("robot2").get("deadlocks").asLong()).isZero();

        // robot1's path east runs into robot2: a near miss
        client.post("robot1/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":9,\"y\":1}");
        sim.step(2);
        JsonNode counters = client.get("world/counters").json();
        assertThat(counters.get("nearMisses").asLong()).isEqualTo(1);
        assertThat(counters.get("perRobot").get("robot1").get("nearMisses").asLong()).isEqualTo(1);
        assertThat(client.get("robot1/robot_local_control/state").json().get("detect").asInt()).isEqualTo(1);
    }

    @Test
    void countersGiveWaitsDoorOpeningsAndCartsInStorage() throws Exception {
        JsonNode c = client.get("world/counters").json();
        assertThat(c.get("stepMillis").asLong()).isEqualTo(500);
        assertThat(c.get("carts").asLong()).isEqualTo(3);
        assertThat(c.get("cartsInStorage").asLong()).isZero();
        assertThat(c.get("doorOpenings").asLong()).isZero();

        client.post("robot1/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":9,\"y\":1}");
        sim.step(5);
        c = client.get("world/counters").json();
        JsonNode r1 = c.get("perRobot").get("robot1");
        assertThat(r1.get("waitSteps").asLong()).isEqualTo(4);
        assertThat(r1.get("waitingSteps").asLong()).isEqualTo(4);
        assertThat(r1.get("longestWaitSteps").asLong()).isEqualTo(4);
        assertThat(r1.get("longestWaitMs").asLong()).isEqualTo(2000);
        assertThat(c.get("longestWaitMs").asLong()).isEqualTo(2000);
        assertThat(c.get("waitingNow").asLong()).isEqualTo(1);
        JsonNode state = client.get("robot1/robot_local_control/state").json();
        assertThat(state.get("waitSteps").asLong()).isEqualTo(4);
        assertThat(state.get("longestWaitSteps").asLong()).isEqualTo(4);

        client.post("robot1/robot_local_control/NavigationComponent/GoToComponent/cancel", "{}");
        sim.step(1);
        c = client.get("world/counters").json();
        assertThat(c.get("waitingNow").asLong()).isZero();
        assertThat(c.get("waitsEnded").asLong()).isEqualTo(1);
        assertThat(c.get("endedWaits").get("4").asLong()).isEqualTo(1);

        // carry cart1 (3,7) through the door to the storage cell (12,1): REQ-1 for one cart
        client.post("door1/door_controller/command", "{\"data\":1.0}");
        String r3 = R3 + "NavigationComponent/";
        client.post(r3 + "GoToComponent/add", "{\"x\":3,\"y\":7}");
        client.post(r3 + "PickComponent/add", "{}");
        client.post(r3 + "GoToComponent/add", "{\"x\":12,\"y\":1}");
        client.post(r3 + "PlaceComponent/add", "{}");
        sim.step(60);
        c = client.get("world/counters").json();
        assertThat(c.get("cartsInStorage").asLong()).isEqualTo(1);
        assertThat(c.get("doorOpenings").asLong()).isEqualTo(1);
        assertThat(c.get("perDoor").get("door1").get("openings").asLong()).isEqualTo(1);
        JsonNode commands = c.get("commands");
        assertThat(commands.get("accepted").asLong()).as("3 go-tos, a pick, a place, a cancel, a door").isEqualTo(7);
        assertThat(commands.get("refused").asLong()).isZero();
        client.post("robot2/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":0,\"y\":0}");
        client.post("robot2/robot_local_control/NavigationComponent/PlaceComponent/add", "{}");
        client.get("robot2/robot_local_control/NavigationComponent/PlaceComponent/query_state");
        sim.faults().setOwn(1, new eu.brain.iot.robotsim.fault.FaultSettings(0, 0, 0, 0, true));
        client.post("robot2/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":2,\"y\":3}");
        commands = client.get("world/counters").json().get("commands");
        assertThat(commands.get("received").asLong()).as("a query is no command").isEqualTo(10);
        assertThat(commands.get("refused").asLong()).as("a place is checked when it starts, not when added")
                .isEqualTo(2);
        assertThat(commands.get("refusedByStatus").get("422").asLong()).as("a goal in a wall").isEqualTo(1);
        assertThat(commands.get("refusedByStatus").get("503").asLong()).as("offline").isEqualTo(1);
        sim.faults().setOwn(1, null);
        sim.step(2);
        JsonNode missions = client.get("world/counters").json().get("missions");
        assertThat(missions.get("finished").asLong()).as("robot3's four missions").isEqualTo(4);
        assertThat(missions.get("cancelled").asLong()).as("robot1's go-to").isEqualTo(1);
        assertThat(missions.get("failed").asLong()).as("robot2's place without a cart").isEqualTo(1);
        c = client.get("world/counters").json();
        assertThat(sim.counters().toString()).as("the Java API answers the same").isEqualTo(c.toString());
        assertThat(sim.worldDocument().get("counters").toString()).isEqualTo(c.toString());
    }

    @Test
    void indexListsRobotsAndDoors() throws Exception {
        JsonNode index = client.get("").json();
        List<String> robots = new ArrayList<>();
        index.get("robots").forEach(n -> robots.add(n.asText()));
        assertThat(robots).containsExactly("robot1", "robot2", "robot3");
        assertThat(index.get("doors").get(0).asText()).isEqualTo("door1");
        assertThat(index.get("manualStep").asBoolean()).isTrue();
    }

    @Test
    void manyPollsShareOneKeepAliveClient() throws Exception {
        for (int i = 0; i < 300; i++) {
            assertThat(client.get("robot" + (1 + i % 3) + "/robot_local_control/state").status()).isEqualTo(200);
        }
    }
}
