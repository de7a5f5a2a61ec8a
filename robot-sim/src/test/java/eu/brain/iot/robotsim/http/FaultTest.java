package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.core.JsonProcessingException;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.fault.FaultSettings;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Each fault, per robot and fleet-wide, set at run time through /admin/faults or by configuration. */
class FaultTest {
    private static final String STATE = "/robot_local_control/state";
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
    void latencyDelaysTheAnswersOfThatRobot() throws Exception {
        assertThat(client.post("admin/faults/robot1", "{\"latencyMs\":300}").status()).isEqualTo(200);
        long t0 = System.nanoTime();
        Client.Answer a = client.get("robot1" + STATE);
        long tookMs = (System.nanoTime() - t0) / 1_000_000;
        assertThat(a.status()).isEqualTo(200);
        assertThat(tookMs).isGreaterThanOrEqualTo(300);
        assertThat(client.get("admin/faults/robot1").json().get("effective").get("latencyMs").asInt())
                .isEqualTo(300);
        assertThat(client.get("admin/faults/robot2").json().get("effective").get("latencyMs").asInt()).isZero();
    }

    @Test
    void errorRateFailsThatShareOfRequestsExactly() throws Exception {
        client.post("admin/faults/robot1", "{\"errorRate\":0.5}");
        List<Integer> statuses = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            statuses.add(client.get("robot1" + STATE).status());
        }
        assertThat(statuses).containsExactly(200, 500, 200, 500, 200, 500);
        assertThat(client.get("robot2" + STATE).status()).isEqualTo(200);
    }

    @Test
    void aFailedOrderChangesNothing() throws Exception {
        client.post("admin/faults/robot3", "{\"errorRate\":1}");
        Client.Answer a = client.post("robot3/robot_local_control/NavigationComponent/GoToComponent/add",
                "{\"x\":6,\"y\":4}");
        assertThat(a.status()).isEqualTo(500);
        assertThat(a.json().get("error").asText()).contains("injected fault");
        client.delete("admin/faults/robot3");
        sim.step(5);
        assertThat(sim.robot("robot3").y()).isEqualTo(1);
        assertThat(sim.robot("robot3").mission()).isNull();
    }

    @Test
    void malformedAnswersAreNotJson() throws Exception {
        client.post("admin/faults/robot2", "{\"malformedRate\":1.0}");
        Client.Answer a = client.get("robot2" + STATE);
        assertThat(a.status()).isEqualTo(200);
        assertThat(a.body()).startsWith("{\"id\":\"robot2\"");
        assertThatThrownBy(() -> Client.JSON.readTree(a.body())).isInstanceOf(JsonProcessingException.class);
        assertThat(Client.JSON.readTree(client.get("robot1" + STATE).body()).get("id").asText()).isEqualTo("robot1");
    }

    @Test
    void droppedConnectionsGiveNoAnswer() throws Exception {
        client.post("admin/faults/robot2", "{\"dropRate\":1}");
        assertThatThrownBy(() -> client.get("robot2" + STATE)).isInstanceOf(IOException.class);
        client.delete("admin/faults/robot2");
        assertThat(client.get("robot2" + STATE).status()).isEqualTo(200);
    }

    @Test
    void offlineRobotAnswers503AndStandsStillUntilItComesBack() throws Exception {
        client.post("robot3/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":6,\"y\":4}");
        client.post("admin/faults/robot3", "{\"offline\":true}");
        Client.Answer a = client.get("robot3" + STATE);
        assertThat(a.status()).isEqualTo(503);
        assertThat(a.json().get("error").asText()).isEqualTo("robot robot3 is offline");
        assertThat(client.post("robot3/robot_local_control/NavigationComponent/GoToComponent/add",
                "{\"x\":8,\"y\":4}").status()).isEqualTo(503);
        sim.step(4);
        assertThat(sim.robot("robot3").y()).isEqualTo(1);

        client.post("admin/faults/robot3", "{\"offline\":false}");
        sim.step(3);
        Client.Answer back = client.get("robot3" + STATE);
        assertThat(back.status()).isEqualTo(200);
        assertThat(back.json().get("y").asInt()).isEqualTo(4);
        assertThat(back.json().get("mission").get("goal").get("x").asInt()).as("the refused order was not queued")
                .isEqualTo(6);
    }

    @Test
    void fleetWideFaultsHitEveryRobotAndARobotsOwnSettingsWin() throws Exception {
        client.post("admin/faults", "{\"errorRate\":1}");
        for (String robot : sim.robotIds()) {
            assertThat(client.get(robot + STATE).status()).as(robot).isEqualTo(500);
        }
        client.post("admin/faults/robot2", "{\"errorRate\":0}");
        assertThat(client.get("robot2" + STATE).status()).isEqualTo(200);
        assertThat(client.get("robot1" + STATE).status()).isEqualTo(500);
        assertThat(client.get("door1/door_controller/state").status()).as("doors and admin are fault-free")
                .isEqualTo(200);
        assertThat(client.get("admin/faults").json().get("robots").has("robot2")).isTrue();
        client.delete("admin/faults");
        for (String robot : sim.robotIds()) {
            assertThat(client.get(robot + STATE).status()).as(robot).isEqualTo(200);
        }
    }

    @Test
    void faultsCanBeConfiguredAtStart() throws Exception {
        sim.close();
        sim = RobotSim.start(SimConfig.builder().manualStep(true)
                .fleetFaults(FaultSettings.NONE.with("errorRate", 1.0))
                .robotFaults("robot3", FaultSettings.NONE.with("offline", true)).build());
        client = new Client(sim.baseUri());
        assertThat(client.get("robot1" + STATE).status()).isEqualTo(500);
        assertThat(client.get("robot3" + STATE).status()).isEqualTo(503);
    }
}
