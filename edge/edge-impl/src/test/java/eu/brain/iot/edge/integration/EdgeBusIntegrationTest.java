package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Instant;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Constants;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.view.RobotView;

/**
 * The edge bundle on the real event bus in Felix, against robot-sim over real HTTP: what it polls reaches
 * behaviours as events; command events from behaviours move robots and doors; a configuration change through
 * Config Admin adds and removes robots in place. Faults: {@link EdgeFaultIntegrationTest}; a whole errand:
 * {@link EdgeRouteIntegrationTest}.
 */
class EdgeBusIntegrationTest extends EdgeBusTestBase {

    private List<String> ids() {
        return model.providers().stream().map(ProviderSnapshot::id).toList();
    }

    private boolean fleetIsUp() {
        List<ProviderSnapshot> providers = model.providers();
        return providers.size() == 4 && providers.stream().allMatch(p -> p.status() == ResourceStatus.OK);
    }

    @Test
    void everyRobotsPositionReachesBehavioursOnTheBus() {
        // The edge announces a robot's first position when it is first seen: here, on the new fleet URL. Between two
        // tests the edge runs on its default configuration (http://127.0.0.1:8090/): a robot-sim someone else runs
        // there may be polled for a moment, so the recorder can hold positions of that fleet too; each robot's
        // newest event is the one that must match this test's simulator (manual steps: its robots stand still).
        await().atMost(DEADLINE).untilAsserted(() -> {
            Map<String, RobotPositionChanged> newest = new HashMap<>();
            for (RobotPositionChanged e : recorder.of(RobotPositionChanged.class)) {
                newest.put(e.robotId, e);
            }
            assertThat(newest.keySet()).containsAll(sim.robotIds());
            for (String id : sim.robotIds()) {
                RobotPositionChanged e = newest.get(id);
                RobotView r = sim.robot(id);
                assertThat(e.x + "," + e.y).as(id).isEqualTo(r.x() + "," + r.y());
                assertThat(e.sourceNode).as("filled in by the bus").isNotNull();
            }
        });
    }

    @Test
    void commandEventsMoveARobotAndTheDoor() {
        await().atMost(DEADLINE).until(this::fleetIsUp);
        OpenDoorCommand open = new OpenDoorCommand();
        open.deviceId = "door1";
        open.commandId = "open-1";
        bus.deliver(open);
        GoToCommand go = EdgeCommands.goTo("robot3", 9, 4);
        go.commandId = "go-1";
        bus.deliver(go);
        await().atMost(DEADLINE).until(() -> recorder.of(CommandOutcome.class).size() == 2);
        assertThat(recorder.of(CommandOutcome.class)).allSatisfy(o -> assertThat(o.accepted).as(o.reason).isTrue())
                .extracting(o -> o.commandId).containsExactlyInAnyOrder("open-1", "go-1");

        sim.step(10);
        await().atMost(DEADLINE).until(() -> recorder.of(RobotPositionChanged.class).stream()
                .anyMatch(e -> e.robotId.equals("robot3") && e.x == 9 && e.y == 4));
        await().atMost(DEADLINE).until(() -> recorder.of(DoorStateChanged.class).stream()
                .anyMatch(e -> e.state.equals("open")));
        assertThat(model.resource("door1", "door", "state").orElseThrow().value()).isEqualTo("open");
    }

    @Test
    void reconfigurationAddsAndRemovesRobotsInPlace() throws Exception {
        Object modelService = context.getServiceReference(DeviceModel.class).getProperty(Constants.SERVICE_ID);
        edge.configureEdge(Map.of("robots", new String[] { "robot1" }));
        await("only robot1").atMost(DEADLINE).until(() -> ids().equals(List.of("robot1")));

        int added = recorder.mark();
        edge.configureEdge(Map.of("robots", new String[] { "robot1", "robot2", "robot3" }));
        await("three robots, polled").atMost(DEADLINE).until(() -> ids().equals(List.of("robot1", "robot2", "robot3"))
                && model.providers().stream().allMatch(p -> p.status() == ResourceStatus.OK));
        // the added robots announce where they stand; robot1 was kept, not made anew: it announces nothing
        await("the added robots' positions").atMost(DEADLINE).until(() -> recorder.since(added,
                RobotPositionChanged.class).stream().map(e -> e.robotId).distinct().sorted().toList()
                .equals(List.of("robot2", "robot3")));
        for (RobotPositionChanged e : recorder.since(added, RobotPositionChanged.class)) {
            assertThat(BusRecorder.at(e)).as(e.robotId).isEqualTo(BusRecorder.at(sim.robot(e.robotId)));
        }
        // and where an added robot goes
        recorder.send(bus, EdgeCommands.goTo("robot2", 4, 4));
        List<String> route = recorder.follow(sim, "robot2", () -> BusRecorder.at(sim.robot("robot2")).equals("4,4"),
                10);
        assertThat(route).startsWith("4,1").endsWith("4,4").hasSizeGreaterThanOrEqualTo(4);

        edge.configureEdge(Map.of("robots", new String[] { "robot2" }));
        await("only robot2").atMost(DEADLINE).until(() -> ids().equals(List.of("robot2")));
        // and no removed robot comes back while robot2 is polled on
        Instant removed = Instant.now().plusMillis(300);
        await("robot2 polled on").atMost(DEADLINE).until(() -> model.provider("robot2").orElseThrow().lastPoll()
                .isAfter(removed));
        assertThat(ids()).containsExactly("robot2");
        assertThat(context.getServiceReference(DeviceModel.class).getProperty(Constants.SERVICE_ID))
                .as("the edge was not restarted").isEqualTo(modelService);
    }
}
