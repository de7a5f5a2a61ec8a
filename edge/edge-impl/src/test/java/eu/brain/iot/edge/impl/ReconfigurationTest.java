package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceRemoved;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.integration.OtherFleets;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.fault.FaultSettings;

/**
 * A new configuration adds and removes devices, or moves to another fleet, without restarting the edge. A device
 * keeps its id across fleets: unreachable at the old one, it is told recovered when the new one answers for it; one
 * the new fleet lacks leaves the model with a {@link DeviceRemoved} event.
 */
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

    private ResourceStatus status(String id) {
        return edge.provider(id).map(ProviderSnapshot::status).orElse(null);
    }

    /** The fault API sets the robot offline until the edge has told it unreachable. */
    private void offline(RobotSim fleet, String robot) {
        fleet.faults().setOwn(fleet.robotIds().indexOf(robot), new FaultSettings(0, 0, 0, 0, true));
        await().atMost(DEADLINE).until(() -> status(robot) == ResourceStatus.UNREACHABLE
                && !sink.of(DeviceUnreachable.class, e -> e.deviceId.equals(robot)).isEmpty());
    }

    private boolean allOk(int providers) {
        return edge.providers().size() == providers
                && edge.providers().stream().allMatch(p -> p.status() == ResourceStatus.OK);
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
    void anUnreachableRobotIsToldRecoveredWhenTheNewFleetAnswersForIt() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings(sim, List.of(), List.of()), sink, EdgeLog.stderr());
        await().atMost(DEADLINE).until(() -> allOk(4));
        offline(sim, "robot2");

        other = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge.configure(settings(other, List.of(), List.of()));
        await().atMost(DEADLINE).until(() -> allOk(4) && edge.settings().baseUrl().equals(other.baseUri()));
        await().atMost(DEADLINE).until(() -> !sink.of(DeviceRecovered.class).isEmpty());
        assertThat(sink.of(DeviceRecovered.class)).extracting(e -> e.deviceId).containsExactly("robot2");
        assertThat(sink.of(DeviceUnreachable.class)).hasSize(1);
        assertThat(sink.of(DeviceRemoved.class)).isEmpty();
        assertThat(ids()).containsExactly("door1", "robot1", "robot2", "robot3");
    }

    @Test
    void aConfiguredRobotIsToldRecoveredAtTheNewFleetTheOthersRemoved() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings(sim, List.of("robot1", "robot2"), List.of()), sink, EdgeLog.stderr());
        await().atMost(DEADLINE).until(() -> allOk(2));
        offline(sim, "robot2");

        other = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge.configure(settings(other, List.of("robot2"), List.of()));
        await().atMost(DEADLINE).until(() -> ids().equals(List.of("robot2")) && status("robot2") == ResourceStatus.OK);
        await().atMost(DEADLINE).until(() -> !sink.of(DeviceRecovered.class).isEmpty());
        assertThat(sink.of(DeviceRecovered.class)).extracting(e -> e.deviceId).containsExactly("robot2");
        assertThat(sink.of(DeviceRemoved.class)).extracting(e -> e.deviceId + ": " + e.reason)
                .containsExactly("robot1: not in the configuration eu.brain.iot.edge any more (robots, doors)");
    }

    @Test
    void aDeviceTheNewFleetLacksIsRemovedAndItsNewOnesAppear() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings(sim, List.of(), List.of()), sink, EdgeLog.stderr());
        await().atMost(DEADLINE).until(() -> allOk(4));
        offline(sim, "robot3");

        other = RobotSim.start(SimConfig.builder().map(OtherFleets.twoRobotsTwoDoors()).manualStep(true).build());
        edge.configure(settings(other, List.of(), List.of()));
        await().atMost(DEADLINE).until(() -> ids().equals(List.of("door1", "door2", "robot1", "robot2"))
                && allOk(4));
        assertThat(sink.of(DeviceRemoved.class)).singleElement().satisfies(e -> {
            assertThat(e.deviceId).isEqualTo("robot3");
            assertThat(e.deviceKind).isEqualTo("robot");
            assertThat(e.reason).isEqualTo("not in the fleet at " + other.baseUri() + " (GET / lists 2 robots, 2 doors)");
        });
        assertThat(sink.of(DeviceRecovered.class)).isEmpty();
    }

    @Test
    void devicesWaitMarkedWhileTheNewFleetDoesNotAnswerAndRecoverWhenItDoes() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings(sim, List.of(), List.of()), sink, EdgeLog.stderr());
        await().atMost(DEADLINE).until(() -> allOk(4));
        offline(sim, "robot2");
        other = RobotSim.start(SimConfig.builder().manualStep(true).build());
        int port = other.port();
        other.close();
        other = null;

        edge.configure(FleetSettings.of("http://127.0.0.1:" + port + "/", List.of(), List.of(), 100, 1000, 8, 1, 2,
                400));
        await().atMost(DEADLINE).until(() -> edge.providers().stream()
                .allMatch(p -> p.reason() != null && p.reason().startsWith("fleet.url changed to http://127.0.0.1:"
                        + port + "/: waiting for its inventory (GET /)")));
        // marked and explained, not live: no values from the other fleet, robot2 still unreachable
        assertThat(edge.providers()).allSatisfy(p -> assertThat(p.services()).as(p.id()).isEmpty())
                .extracting(p -> p.id() + " " + p.status())
                .containsExactly("door1 STALE", "robot1 STALE", "robot2 UNREACHABLE", "robot3 STALE");

        other = RobotSim.start(SimConfig.builder().manualStep(true).port(port).build());
        await().atMost(DEADLINE).until(() -> allOk(4));
        await().atMost(DEADLINE).until(() -> !sink.of(DeviceRecovered.class).isEmpty());
        assertThat(sink.of(DeviceRecovered.class)).extracting(e -> e.deviceId).containsExactly("robot2");
        assertThat(sink.of(DeviceUnreachable.class)).hasSize(1);
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
