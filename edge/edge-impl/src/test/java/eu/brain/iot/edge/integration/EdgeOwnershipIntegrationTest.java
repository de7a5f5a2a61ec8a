package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceRemoved;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The edge owning part of the fleet, in the framework: configured (Config Admin) as node 1 of 2 it polls robot2 and
 * door1 only and the others leave its model with {@code DeviceRemoved}; through the {@link DeviceOwnership} service
 * it takes robot3 over mid-errand (polled at once, announced as on discovery, its mission's end told on the bus)
 * and releases robot2; every command it sends names the node ({@code fabric.node.name=edge-itest} in test.bndrun)
 * in robot-sim's record.
 */
class EdgeOwnershipIntegrationTest extends EdgeBusTestBase {

    @InjectService(timeout = 5_000)
    DeviceOwnership ownership;
    @InjectService(timeout = 5_000)
    PollMonitor monitor;

    private void awaitProviders(String... ids) {
        await("the edge's providers " + List.of(ids) + ", all OK").atMost(DEADLINE).untilAsserted(() -> {
            List<ProviderSnapshot> providers = model.providers();
            assertThat(providers).extracting(ProviderSnapshot::id).containsExactly(ids);
            assertThat(providers).allSatisfy(p -> assertThat(p.status()).isEqualTo(ResourceStatus.OK));
        });
    }

    @Test
    void aNodePollsItsShareTakesAndReleasesDevicesAtRunTimeAndNamesItselfOnEveryCommand() throws Exception {
        assertThat(ownership.nodeName()).isEqualTo("edge-itest");
        assertThat(ownership.owned()).as("share all by default").containsExactly("door1", "robot1", "robot2",
                "robot3");

        // node 1 of 2: robot2 (2 mod 2 = 0) and the door
        int mark = recorder.mark();
        edge.configureEdge(Map.of("share", "1/2"));
        awaitProviders("door1", "robot2");
        await("robot1 and robot3 told removed").atMost(DEADLINE).until(() -> recorder.since(mark,
                DeviceRemoved.class).size() == 2);
        assertThat(recorder.since(mark, DeviceRemoved.class)).allSatisfy(e -> assertThat(e.reason)
                .contains("not owned by node edge-itest")).extracting(e -> e.deviceId)
                .containsExactlyInAnyOrder("robot1", "robot3");
        assertThat(ownership.owned()).containsExactly("door1", "robot2");
        // not polled: no event about them since their removal while the owned ones are polled on
        int afterRemoval = recorder.mark();
        Instant later = Instant.now().plusMillis(300);
        await("the owned devices polled on").atMost(DEADLINE).until(() -> model.providers().stream()
                .allMatch(p -> p.lastPoll().isAfter(later)));
        assertThat(recorder.since(afterRemoval, BrainIoTEvent.class)).noneMatch(e -> e instanceof RobotPositionChanged r
                && !r.robotId.equals("robot2"));

        // a command for robot2 carries the node's name; one for robot1 is refused: not this node's
        assertThat(recorder.send(bus, EdgeCommands.goTo("robot2", 4, 3)).accepted).isTrue();
        assertThat(sim.commandOrigins().robots().get("robot2").node()).isEqualTo("edge-itest");
        CommandOutcome refused = sendUnchecked(EdgeCommands.goTo("robot1", 2, 4));
        assertThat(refused.accepted).isFalse();
        assertThat(refused.reason).contains("unknown device 'robot1'");

        // robot3 is on an errand another node gave it (node2, straight to robot-sim)
        long mission = postGoTo("robot3", 6, 4);
        sim.step(1);
        int beforeTake = recorder.mark();
        assertThat(ownership.take(Set.of("robot3"))).containsExactly("robot3");
        awaitProviders("door1", "robot2", "robot3");
        await("robot3 announced as first seen").atMost(DEADLINE).until(() -> recorder.since(beforeTake,
                RobotPositionChanged.class).stream().anyMatch(e -> e.robotId.equals("robot3") && e.previousX == null));
        sim.step(10);
        await("robot3's errand's end told by its new owner").atMost(DEADLINE).until(() -> recorder.since(beforeTake,
                MissionFinished.class).stream().anyMatch(e -> e.robotId.equals("robot3") && e.missionId == mission));
        assertThat(recorder.send(bus, EdgeCommands.goTo("robot3", 6, 3)).accepted).isTrue();
        assertThat(sim.commandOrigins().changes()).singleElement().satisfies(c -> {
            assertThat(c.robot()).isEqualTo("robot3");
            assertThat(c.to()).isEqualTo("edge-itest");
        });

        // robot2 released: removed from the model, told on the bus, commanded no more
        int beforeRelease = recorder.mark();
        assertThat(ownership.release(Set.of("robot2"))).containsExactly("robot2");
        awaitProviders("door1", "robot3");
        assertThat(recorder.since(beforeRelease, DeviceRemoved.class)).singleElement()
                .satisfies(e -> assertThat(e.deviceId).isEqualTo("robot2"));
        assertThat(sendUnchecked(EdgeCommands.goTo("robot2", 4, 4)).accepted).isFalse();
    }

    /** A goTo for the robot straight to robot-sim, as another node would send it; its mission id. */
    private long postGoTo(String robot, int x, int y) throws Exception {
        var answer = edge.http().send(java.net.http.HttpRequest.newBuilder(sim.baseUri().resolve(robot
                + "/robot_local_control/NavigationComponent/GoToComponent/add"))
                .header("Content-Type", "application/json").header("X-Brain-Node", "node2")
                .POST(java.net.http.HttpRequest.BodyPublishers.ofString("{\"x\":" + x + ",\"y\":" + y + "}")).build(),
                java.net.http.HttpResponse.BodyHandlers.ofString());
        assertThat(answer.statusCode()).as(answer.body()).isEqualTo(200);
        return EdgeTestSupport.JSON.readTree(answer.body()).path("mission").path("id").asLong();
    }

    /** Publishes a command and returns its outcome, accepted or not. */
    private CommandOutcome sendUnchecked(eu.brain.iot.edge.api.EdgeCommand command) {
        command.commandId = "unchecked-" + System.nanoTime();
        bus.deliver(command);
        return await("the outcome of " + command.commandId).atMost(DEADLINE).until(() -> recorder.of(
                CommandOutcome.class).stream().filter(o -> o.commandId.equals(command.commandId)).findFirst()
                .orElse(null), o -> o != null);
    }
}
