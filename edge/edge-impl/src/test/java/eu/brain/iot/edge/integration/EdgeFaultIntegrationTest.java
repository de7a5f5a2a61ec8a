package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.BACKOFF_MAX_MS;
import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.awaitility.core.ThrowingRunnable;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.robotsim.fault.FaultSettings;

/**
 * Every fault robot-sim can inject, on robot2, seen through the bus in Felix (the in-framework twin of the unit
 * test FaultRecoveryTest): robot2 is reported unreachable once, with the fault as the reason, and marked so in the
 * device model; robot1 goes on being polled and its moves reach the bus meanwhile; once the fault is cleared robot2
 * is reported recovered once and is OK again.
 */
class EdgeFaultIntegrationTest extends EdgeBusTestBase {

    @Override
    Map<String, Object> edgeSettings() {
        return EdgeTestSupport.FAIL_FAST;
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "timeout        | {\"latencyMs\":2000}   | no answer within 500 ms",
            "HTTP 500       | {\"errorRate\":1.0}    | HTTP 500",
            "malformed JSON | {\"malformedRate\":1.0} | malformed JSON from robot2",
            "dropped        | {\"dropRate\":1.0}     | closed the connection without answering",
            "offline        | {\"offline\":true}     | HTTP 503: robot robot2 is offline" })
    void aFaultyRobotIsReportedOnceAndRecoversWhileAnotherKeepsMoving(String fault, String json, String reason)
            throws Exception {
        int robot2 = sim.robotIds().indexOf("robot2");
        sim.faults().setOwn(robot2, EdgeTestSupport.JSON.readValue(json, FaultSettings.class));

        await("robot2 reported unreachable").atMost(DEADLINE).until(() -> !recorder.of(DeviceUnreachable.class)
                .isEmpty());
        assertThat(recorder.of(DeviceUnreachable.class)).singleElement().satisfies(e -> {
            assertThat(e.deviceId).isEqualTo("robot2");
            assertThat(e.deviceKind).isEqualTo("robot");
            assertThat(e.reason).contains(reason);
        });
        await("robot2 unreachable in the model").atMost(DEADLINE).untilAsserted(() -> {
            assertThat(model.provider("robot2").orElseThrow().status()).isEqualTo(ResourceStatus.UNREACHABLE);
            assertThat(model.provider("robot2").orElseThrow().reason()).contains(reason);
            assertThat(model.resource("robot2", "position", "x").orElseThrow().status())
                    .isEqualTo(ResourceStatus.UNREACHABLE);
        });

        // meanwhile robot1 is polled on: every cell of its way reaches the bus
        int down = recorder.mark();
        recorder.send(bus, EdgeCommands.goTo("robot1", 2, 4));
        List<String> route = recorder.follow(sim, "robot1", () -> BusRecorder.at(sim.robot("robot1")).equals("2,4"),
                10);
        assertThat(recorder.since(down, RobotPositionChanged.class)).extracting(BusRecorder::at)
                .containsExactlyElementsOf(route.subList(1, route.size())).hasSizeGreaterThanOrEqualTo(3);
        assertThat(model.provider("robot1").orElseThrow().status()).isEqualTo(ResourceStatus.OK);
        // robot2, polled with backoff all along, stays reported once
        holds("robot2 reported once while it is down", Duration.ofMillis(2 * BACKOFF_MAX_MS), () -> {
            assertThat(recorder.of(DeviceUnreachable.class)).hasSize(1);
            assertThat(model.provider("robot2").orElseThrow().status()).isEqualTo(ResourceStatus.UNREACHABLE);
        });

        sim.faults().setOwn(robot2, null);
        await("robot2 reported recovered").atMost(DEADLINE).until(() -> !recorder.of(DeviceRecovered.class)
                .isEmpty());
        // polled every 100 ms again: a second report would come within a few polls
        holds("robot2 reported recovered once", Duration.ofMillis(300), () -> {
            assertThat(recorder.of(DeviceRecovered.class)).hasSize(1);
            assertThat(recorder.of(DeviceUnreachable.class)).hasSize(1);
            assertThat(model.provider("robot2").orElseThrow().status()).isEqualTo(ResourceStatus.OK);
        });
        assertThat(recorder.of(DeviceRecovered.class)).singleElement()
                .satisfies(e -> assertThat(e.deviceId).isEqualTo("robot2"));
        assertThat(model.resource("robot2", "position", "x").orElseThrow().status()).isEqualTo(ResourceStatus.OK);
        List<BrainIoTEvent> all = recorder.all();
        assertThat(all.indexOf(recorder.of(DeviceRecovered.class).get(0)))
                .isGreaterThan(all.indexOf(recorder.of(DeviceUnreachable.class).get(0)));
    }

    /** The assertion holds now and keeps holding for that long (fails as soon as it does not). */
    private static void holds(String what, Duration duration, ThrowingRunnable assertion) {
        await(what).during(duration).atMost(duration.plusSeconds(1)).untilAsserted(assertion);
    }
}
