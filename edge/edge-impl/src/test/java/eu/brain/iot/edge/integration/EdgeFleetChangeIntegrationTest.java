package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceRemoved;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.RobotEvent;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.fault.FaultSettings;

/**
 * The edge reconfigured (Config Admin) to another fleet URL while a robot of the first fleet is offline, as the
 * warehouse itests do between two tests: each runs its own robot-sim, and a test may end with a robot offline (issue
 * seen in CI: PaperWarehouseIntegrationTest's behaviours met the robots UNREACHABLE and never heard them recover).
 * The devices keep their ids: one the new fleet answers for is OK within a few polls and a behaviour that heard
 * DeviceUnreachable for it hears DeviceRecovered; one the new fleet does not have leaves the model with a
 * DeviceRemoved event; a new one appears.
 */
class EdgeFleetChangeIntegrationTest extends EdgeBusTestBase {

    /**
     * How soon after the edge took the new URL every device of the new fleet must be OK: its inventory, then one
     * poll period (100 ms) to spread the first polls over. 30 periods: room for a loaded 2-core machine.
     */
    private static final Duration FEW_POLLS = Duration.ofSeconds(3);
    private static final FaultSettings OFFLINE = new FaultSettings(0, 0, 0, 0, true);

    @InjectService(timeout = 5_000)
    PollMonitor monitor;

    /** The second fleet, closed after the edge left it (closed earlier, its devices would become unreachable). */
    private RobotSim other;

    @Override
    Map<String, Object> edgeSettings() {
        return EdgeTestSupport.FAIL_FAST;
    }

    @AfterEach
    @Override
    void stop() throws Exception {
        try {
            super.stop();
        } finally {
            if (other != null) {
                other.close();
            }
        }
    }

    @Test
    void aRobotUnreachableAtTheOldFleetIsToldRecoveredWhenTheNewFleetAnswersForIt() throws Exception {
        // robot1 goes somewhere first, so that the values of the new fleet (robot1 docked) are told from the old ones
        recorder.send(bus, EdgeCommands.goTo("robot1", 2, 4));
        recorder.follow(sim, "robot1", () -> BusRecorder.at(sim.robot("robot1")).equals("2,4"), 10);
        goesOffline("robot2");

        other = RobotSim.start(SimConfig.builder().manualStep(true).build());
        int mark = recorder.mark();
        edge.configureEdge(Map.of("fleet.url", other.baseUri().toString()));
        awaitEveryDeviceOkAt(other);

        await("robot2 told recovered").atMost(DEADLINE).until(() -> !recorder.since(mark, DeviceRecovered.class)
                .isEmpty());
        assertThat(recorder.of(DeviceRecovered.class)).singleElement().satisfies(e -> {
            assertThat(e.deviceId).isEqualTo("robot2");
            assertThat(e.deviceKind).isEqualTo("robot");
        });
        assertThat(recorder.of(DeviceUnreachable.class)).as("told unreachable once, never again").hasSize(1);
        assertThat(recorder.of(DeviceRemoved.class)).as("the new fleet has every device").isEmpty();
        List<BrainIoTEvent> all = recorder.all();
        assertThat(all.indexOf(recorder.of(DeviceRecovered.class).get(0)))
                .isGreaterThan(all.indexOf(recorder.of(DeviceUnreachable.class).get(0)));
        // the model and the bus show the new fleet's robots, not the old fleet's (whose robot2 is still offline)
        for (String robot : other.robotIds()) {
            String there = BusRecorder.at(other.robot(robot));
            assertThat(model.resource(robot, "position", "x").orElseThrow().value() + ","
                    + model.resource(robot, "position", "y").orElseThrow().value()).as(robot).isEqualTo(there);
            await(robot + " announced where it stands in the new fleet").atMost(DEADLINE)
                    .until(() -> recorder.since(mark, RobotPositionChanged.class).stream()
                            .anyMatch(e -> e.robotId.equals(robot) && BusRecorder.at(e).equals(there)));
        }
        assertThat(BusRecorder.at(sim.robot("robot1"))).as("robot1 of the old fleet").isEqualTo("2,4");
    }

    @Test
    void aDeviceTheNewFleetLacksIsRemovedWithAnEventAndItsNewDevicesAppear() throws Exception {
        goesOffline("robot3");

        other = RobotSim.start(SimConfig.builder().map(OtherFleets.twoRobotsTwoDoors()).manualStep(true).build());
        int mark = recorder.mark();
        edge.configureEdge(Map.of("fleet.url", other.baseUri().toString()));
        awaitEveryDeviceOkAt(other);

        await("robot3 told removed").atMost(DEADLINE).until(() -> !recorder.of(DeviceRemoved.class).isEmpty());
        assertThat(recorder.of(DeviceRemoved.class)).singleElement().satisfies(e -> {
            assertThat(e.deviceId).isEqualTo("robot3");
            assertThat(e.deviceKind).isEqualTo("robot");
            assertThat(e.reason).contains("not in the fleet at " + other.baseUri());
        });
        assertThat(model.provider("robot3")).as("robot3 left the model").isEmpty();
        assertThat(recorder.of(DeviceRecovered.class)).as("robot3 never answered again; the others never failed")
                .isEmpty();
        await("door2, new, announced").atMost(DEADLINE).until(() -> recorder.since(mark, DoorStateChanged.class)
                .stream().anyMatch(e -> e.doorId.equals("door2") && e.previousState == null));
        // and robot3 is polled no more: none of its events, no second removal, while the others are polled on
        Instant later = Instant.now().plusMillis(500);
        await("the new fleet polled on").atMost(DEADLINE).until(() -> model.providers().stream()
                .allMatch(p -> p.lastPoll().isAfter(later)));
        assertThat(recorder.since(mark, BrainIoTEvent.class)).filteredOn(e -> mentions(e, "robot3"))
                .as("events about robot3 since the change").singleElement().isInstanceOf(DeviceRemoved.class);
    }

    /** The robot-sim fault API sets the robot offline until the edge reports it unreachable (bus and model). */
    private void goesOffline(String robot) {
        sim.faults().setOwn(sim.robotIds().indexOf(robot), OFFLINE);
        await(robot + " reported unreachable").atMost(DEADLINE).until(() -> recorder.of(DeviceUnreachable.class)
                .stream().anyMatch(e -> e.deviceId.equals(robot)));
        await(robot + " unreachable in the model").atMost(DEADLINE).until(() -> model.provider(robot).orElseThrow()
                .status() == ResourceStatus.UNREACHABLE);
    }

    /**
     * Waits until the edge polls the fleet at that URL (Config Admin applies a configuration later), then until every
     * device of that fleet, and only those, is OK in the model: within {@link #FEW_POLLS}.
     */
    private void awaitEveryDeviceOkAt(RobotSim fleet) {
        await("the edge polls " + fleet.baseUri()).atMost(DEADLINE)
                .until(() -> fleet.baseUri().toString().equals(monitor.statistics().fleetUrl));
        List<String> ids = Stream.concat(fleet.robotIds().stream(), fleet.doorIds().stream()).sorted().toList();
        await("every device of " + fleet.baseUri() + " OK").atMost(FEW_POLLS).untilAsserted(() -> {
            List<ProviderSnapshot> providers = model.providers();
            assertThat(providers).extracting(ProviderSnapshot::id).containsExactlyElementsOf(ids);
            // OK: answered since the change (a device of the old fleet is STALE or UNREACHABLE until then)
            assertThat(providers).allSatisfy(p -> assertThat(p.status()).as(p.id() + ": " + p.reason())
                    .isEqualTo(ResourceStatus.OK));
        });
    }

    private static boolean mentions(BrainIoTEvent e, String device) {
        return e instanceof DeviceUnreachable u && u.deviceId.equals(device)
                || e instanceof DeviceRecovered r && r.deviceId.equals(device)
                || e instanceof DeviceRemoved d && d.deviceId.equals(device)
                || e instanceof RobotEvent robot && robot.robotId.equals(device);
    }
}
