package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.fault.FaultSettings;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * HTTP/1.1 pipelining: requests sent back to back on one connection are answered in request order, and each takes
 * effect before the next is looked at. Answers are told apart by their content.
 */
class PipeliningTest {
    private static final String JSON = "Content-Type: application/json";
    private RobotSim sim;
    private String host;

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        host = "Host: 127.0.0.1:" + sim.port();
    }

    @AfterEach
    void stop() {
        sim.close();
    }

    /** What an answer must say to be the answer of a request, and the request. */
    private record Expected(String request, String what, String field, String value) {
    }

    @Test
    void answersComeInRequestOrderEvenWhenOneRobotIsSlow() throws Exception {
        // robot1 answers 150 ms late; robot2, the door, the world and robot3's orders answer at once
        sim.faults().setOwn(0, FaultSettings.NONE.with("latencyMs", 150));
        List<Expected> burst = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            burst.add(new Expected(RawHttp.request("GET", "/robot1/robot_local_control/state", null, host),
                    "robot1's state", "id", "robot1"));
            burst.add(new Expected(RawHttp.request("POST",
                    "/robot3/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":" + (6 + i % 4)
                            + ",\"y\":4}", host, JSON), "robot3's order " + i, "robot", "robot3"));
            burst.add(new Expected(RawHttp.request("GET", "/robot2/robot_local_control/state", null, host),
                    "robot2's state", "id", "robot2"));
            burst.add(new Expected(RawHttp.request("GET", "/door1/door_controller/state", null, host),
                    "door1's state", "id", "door1"));
            burst.add(new Expected(RawHttp.request("GET", "/world/counters", null, host),
                    "the counters", "step", "0"));
            burst.add(new Expected(RawHttp.request("GET", "/robot7/robot_local_control/state", null, host),
                    "the 404 for robot7", "error", "unknown robot 'robot7'"));
        }
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(String.join("", burst.stream().map(Expected::request).toList()));
            long lastMission = 0;
            for (int i = 0; i < burst.size(); i++) {
                Expected e = burst.get(i);
                JsonNode answer = c.read().json();
                assertThat(answer.path(e.field()).asText()).as("answer %d must be %s: %s", i, e.what(), answer)
                        .isEqualTo(e.value());
                if (e.value().equals("robot3")) {
                    long id = answer.get("mission").get("id").asLong();
                    assertThat(id).as("robot3's orders queued in request order").isGreaterThan(lastMission);
                    lastMission = id;
                }
            }
        }
    }

    @Test
    void anOrderTakesEffectBeforeTheNextPipelinedRequestIsAnswered() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(RawHttp.request("POST", "/robot3/robot_local_control/NavigationComponent/GoToComponent/add",
                    "{\"x\":6,\"y\":4}", host, JSON)
                    + RawHttp.request("GET", "/robot3/robot_local_control/state", null, host)
                    + RawHttp.request("POST", "/admin/step", "{\"steps\":1}", host, JSON)
                    + RawHttp.request("GET", "/robot3/robot_local_control/state", null, host));
            long id = c.read().json().get("mission").get("id").asLong();
            JsonNode before = c.read().json();
            assertThat(before.get("mission").get("id").asLong()).as("the state after the order shows it").isEqualTo(id);
            assertThat(before.get("mission").get("state").asText()).isEqualTo("queued");
            assertThat(c.read().json().get("step").asLong()).isEqualTo(1);
            JsonNode after = c.read().json();
            assertThat(after.get("y").asInt()).as("one step south").isEqualTo(2);
            assertThat(after.get("mission").get("state").asText()).isEqualTo("running");
        }
    }

    @Test
    void aLongBurstOfPollsComesBackInOrder() throws Exception {
        int n = 600;
        StringBuilder burst = new StringBuilder();
        for (int i = 0; i < n; i++) {
            burst.append(RawHttp.request("GET", "/robot" + (1 + i % 3) + "/robot_local_control/state", null, host));
        }
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(burst.toString());
            for (int i = 0; i < n; i++) {
                assertThat(c.read().json().get("id").asText()).as("answer %d", i).isEqualTo("robot" + (1 + i % 3));
            }
        }
    }

    @Test
    void aBurstEndingInConnectionCloseIsAnsweredThenClosed() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(RawHttp.request("GET", "/robot1/robot_local_control/state", null, host)
                    + RawHttp.request("GET", "/robot2/robot_local_control/state", null, host, "Connection: close")
                    + RawHttp.request("GET", "/robot3/robot_local_control/state", null, host));
            assertThat(c.read().json().get("id").asText()).isEqualTo("robot1");
            RawHttp.Answer last = c.read();
            assertThat(last.json().get("id").asText()).isEqualTo("robot2");
            assertThat(last.headers().get("connection")).isEqualTo("close");
            assertThat(c.closedByServer()).as("nothing is answered after Connection: close").isTrue();
        }
    }
}
