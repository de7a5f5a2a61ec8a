package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/** Without manual stepping the world moves by itself, at the configured speed. */
class ClockTest {

    @Test
    void robotsMoveOnTheirOwnAtTheConfiguredSpeed() throws Exception {
        try (RobotSim sim = RobotSim.start(SimConfig.builder().speed(100).build())) {
            Client client = new Client(sim.baseUri());
            assertThat(client.post("robot3/robot_local_control/NavigationComponent/GoToComponent/add",
                    "{\"x\":6,\"y\":4}").status()).isEqualTo(200);
            await().atMost(Duration.ofSeconds(20)).untilAsserted(() -> {
                var state = client.get("robot3/robot_local_control/state").json();
                assertThat(state.get("y").asInt()).isEqualTo(4);
                assertThat(state.get("mission").get("state").asText()).isEqualTo("finished");
            });
            long steps = sim.inspect(w -> w.step());
            assertThat(steps).isGreaterThanOrEqualTo(3);
        }
    }
}
