package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/** A new configuration adds and removes devices, or moves to another fleet, without restarting the edge. */
class ReconfigurationTest {

    private static final Duration DEADLINE = Duration.ofSeconds(10);

    private RobotSim sim;
    private RobotSim other;
    private Edge edge;
    private final RecordingSink sink = new RecordingSink();

    @AfterEach
    void stop() {
        if (edge != null) {
            edge.close();
        }
        if (sim != null) {
            sim.close();
        }
        if (other != null) {
            other.close();
        }
    }

    private FleetSettings settings(RobotSim fleet, List<String> robots, List<String> doors) {
        return FleetSettings.of(fleet.baseUri().toString(), robots, doors, 100, 1000, 8, 1, 2, 400);
    }

    private List<String> ids() {
        return edge.providers().stream().map(ProviderSnapshot::id).toList();
    }

    @Test
    void robotsAreAddedAndRemovedInPlace() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings(sim, List.of("robot1"), List.of()), sink, EdgeLog.stderr());
        await().atMost(DEADLINE).until(() -> edge.provider("robot1").map(p -> p.status() == ResourceStatus.OK)
                .orElse(false));
        assertThat(ids()).containsExactly("robot1");

        edge.configure(settings(sim, List.of("robot1", "robot2", "robot3"), List.of("door1")));
        await().atMost(DEADLINE).until(() -> edge.providers().size() == 4
                && edge.providers().stream().allMatch(p -> p.status() == ResourceStatus.OK));
        // robot1 was kept, not re-created: its first position was announced once only
        assertThat(sink.of(RobotPositionChanged.class, e -> e.robotId.equals("robot1"))).hasSize(1);

        edge.configure(settings(sim, List.of("robot3"), List.of()));
        await().atMost(DEADLINE).until(() -> ids().equals(List.of("robot3")));
        long polls = edge.pollStats().answered();
        await().atMost(DEADLINE).until(() -> edge.pollStats().answered() > polls + 5);
        assertThat(ids()).containsExactly("robot3");
    }

    @Test
    void anEmptyListMeansAskTheFleetAndANewUrlMovesToAnotherFleet() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings(sim, List.of("robot2"), List.of()), sink, EdgeLog.stderr());
        await().atMost(DEADLINE).until(() -> ids().equals(List.of("robot2")));

        edge.configure(settings(sim, List.of(), List.of()));
        await().atMost(DEADLINE).until(() -> ids().equals(List.of("door1", "robot1", "robot2", "robot3")));

        other = RobotSim.start(SimConfig.builder().manualStep(true).build());
        other.step(1);
        edge.configure(settings(other, List.of("robot1"), List.of()));
        await().atMost(DEADLINE).until(() -> ids().equals(List.of("robot1"))
                && edge.provider("robot1").orElseThrow().status() == ResourceStatus.OK);
        assertThat(edge.settings().baseUrl()).isEqualTo(other.baseUri());
    }

    @Test
    void aFleetThatIsNotUpYetIsFoundWhenItStarts() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        int port = sim.port();
        sim.close();
        sim = null;
        edge = new Edge(FleetSettings.of("http://127.0.0.1:" + port + "/", List.of(), List.of(), 100, 300, 8, 1, 2,
                200), sink, EdgeLog.stderr());
        assertThat(edge.providers()).isEmpty();
        sim = RobotSim.start(SimConfig.builder().manualStep(true).port(port).build());
        await().atMost(DEADLINE).until(() -> edge.providers().size() == 4);
    }
}
