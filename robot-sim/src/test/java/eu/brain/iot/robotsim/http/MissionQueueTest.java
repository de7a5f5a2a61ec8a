package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import org.junit.jupiter.api.Test;

/** A robot's queue of missions is bounded: one order more is a 429 that says the bound and what to do. */
class MissionQueueTest {
    private static final String R1 = "robot1/robot_local_control/NavigationComponent/";

    @Test
    void theDefaultBoundIs64Missions() throws Exception {
        try (RobotSim sim = RobotSim.start(SimConfig.builder().manualStep(true).build())) {
            Client client = new Client(sim.baseUri());
            for (int i = 0; i < 64; i++) {
                assertThat(client.post(R1 + "GoToComponent/add", "{\"x\":" + (2 + i % 8) + ",\"y\":3}").status())
                        .as("order %d", i).isEqualTo(200);
            }
            Client.Answer full = client.post(R1 + "GoToComponent/add", "{\"x\":3,\"y\":3}");
            assertThat(full.status()).isEqualTo(429);
            assertThat(full.json().get("status").asInt()).isEqualTo(429);
            assertThat(full.json().get("error").asText()).isEqualTo("robot1's mission queue is full: 64 missions "
                    + "wait (the bound is 64, robot-sim's --max-queue): wait until queued missions start, or cancel "
                    + "some (POST .../GoToComponent/cancel)");
            assertThat(client.get(R1 + "GoToComponent/query_state").json().get("queued")).hasSize(64);
            assertThat(client.post("robot2/robot_local_control/NavigationComponent/GoToComponent/add",
                    "{\"x\":3,\"y\":3}").status()).as("the bound is per robot").isEqualTo(200);
        }
    }

    @Test
    void everyKindOfMissionCountsAndRoomComesBack() throws Exception {
        try (RobotSim sim = RobotSim.start(SimConfig.builder().manualStep(true).maxQueuedMissions(3).build())) {
            Client client = new Client(sim.baseUri());
            assertThat(client.post(R1 + "GoToComponent/add", "{\"x\":2,\"y\":3}").status()).isEqualTo(200);
            assertThat(client.post(R1 + "PickComponent/add", "").status()).isEqualTo(200);
            assertThat(client.post(R1 + "PlaceComponent/add", "").status()).isEqualTo(200);
            for (String refused : new String[] {"GoToComponent/add", "PickComponent/add", "PlaceComponent/add"}) {
                Client.Answer a = client.post(R1 + refused, refused.startsWith("GoTo") ? "{\"x\":2,\"y\":2}" : "");
                assertThat(a.status()).as(refused).isEqualTo(429);
                assertThat(a.json().get("error").asText()).contains("3 missions wait (the bound is 3");
            }
            sim.step(1); // the go-to starts: it leaves the queue
            assertThat(client.post(R1 + "GoToComponent/add", "{\"x\":2,\"y\":2}").status()).isEqualTo(200);
            assertThat(client.post(R1 + "GoToComponent/add", "{\"x\":2,\"y\":2}").status()).isEqualTo(429);
            assertThat(client.post(R1 + "PickComponent/cancel", "").json().get("cancelled")).hasSize(1);
            assertThat(client.post(R1 + "GoToComponent/add", "{\"x\":2,\"y\":2}").status()).isEqualTo(200);
        }
    }
}
