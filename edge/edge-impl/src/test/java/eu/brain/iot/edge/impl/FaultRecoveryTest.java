package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.model.api.ResourceStatus;

/**
 * Every fault robot-sim can inject, on one robot: the robot is marked and reported once, the other robots keep
 * being polled on time, and the robot recovers by itself once the fault is cleared.
 */
class FaultRecoveryTest {

    private static final Duration DEADLINE = Duration.ofSeconds(15);

    // 100 ms period, 1 s timeout (a healthy robot must not time out on a loaded machine: it would be reported too),
    // unreachable after 2 failures, backoff up to 400 ms
    @RegisterExtension
    final EdgeOnSim fleet = new EdgeOnSim(url -> FleetSettings.of(url, List.of(), List.of(), 100, 1000, 8, 1, 2, 400));

    @BeforeEach
    void allPolled() {
        fleet.awaitAllOk(4);
    }

    @Test
    void aPollThatNeverLeftTheEdgeDoesNotMakeAHealthyDeviceUnreachable() {
        // one connection for the whole fleet, held 300 ms (the timeout) by every poll of two robots that do not
        // answer: the other devices' polls wait for it, behind both, and time out before they are sent
        fleet.restart(url -> FleetSettings.of(url, List.of(), List.of(), 100, 300, 1, 1, 1, 400));
        fleet.awaitAllOk(4);
        // a healthy device goes stale only when its poll could not be sent
        java.util.Set<String> staleHealthy = java.util.concurrent.ConcurrentHashMap.newKeySet();
        fleet.edge.subscribe(null, null, v -> {
            if (v.status() != ResourceStatus.OK && !v.provider().equals("robot2") && !v.provider().equals("robot3")) {
                staleHealthy.add(v.provider() + " " + v.status());
            }
        });
        SimAdmin.fault(fleet.sim, "robot2", "{\"latencyMs\":2000}");
        SimAdmin.fault(fleet.sim, "robot3", "{\"latencyMs\":2000}");

        await().atMost(DEADLINE).until(() -> !staleHealthy.isEmpty());
        assertThat(staleHealthy).allSatisfy(s -> assertThat(s).endsWith(" STALE"));
        await().atMost(DEADLINE).until(() -> fleet.sink.of(DeviceUnreachable.class).size() >= 2);
        SimAdmin.clear(fleet.sim, "robot2");
        SimAdmin.clear(fleet.sim, "robot3");
        fleet.awaitAllOk(4);
        assertThat(fleet.sink.of(DeviceUnreachable.class)).extracting(e -> e.deviceId)
                .containsExactlyInAnyOrder("robot2", "robot3");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "timeout        | {\"latencyMs\":2000}   | no answer within 1000 ms",
            "HTTP 500       | {\"errorRate\":1.0}    | HTTP 500",
            "malformed JSON | {\"malformedRate\":1.0} | malformed JSON from robot2 at line 1",
            "dropped        | {\"dropRate\":1.0}     | closed the connection without answering",
            "offline        | {\"offline\":true}     | HTTP 503: robot robot2 is offline" })
    void aFaultyRobotIsReportedOnceAndRecoversWhileOthersKeepBeingPolled(String fault, String json, String reason) {
        SimAdmin.fault(fleet.sim, "robot2", json);

        await().atMost(DEADLINE).until(() -> fleet.edge.provider("robot2").orElseThrow().status()
                == ResourceStatus.UNREACHABLE);
        assertThat(fleet.edge.provider("robot2").orElseThrow().reason()).contains(reason);
        assertThat(fleet.edge.resource("robot2", "position", "x").orElseThrow().status())
                .isEqualTo(ResourceStatus.UNREACHABLE);
        List<DeviceUnreachable> reports = fleet.sink.of(DeviceUnreachable.class);
        assertThat(reports).singleElement().satisfies(e -> {
            assertThat(e.deviceId).isEqualTo("robot2");
            assertThat(e.reason).contains(reason);
        });

        // the others are still polled and current while robot2 is down
        long answeredBefore = fleet.edge.pollStats().answered();
        await().atMost(DEADLINE).until(() -> fleet.edge.pollStats().answered() >= answeredBefore + 20);
        assertThat(fleet.edge.provider("robot1").orElseThrow().status()).isEqualTo(ResourceStatus.OK);
        assertThat(fleet.edge.provider("robot3").orElseThrow().status()).isEqualTo(ResourceStatus.OK);

        // still reported only once after many more failed polls (backoff keeps polling it)
        long failedBefore = fleet.edge.pollStats().failed();
        await().atMost(DEADLINE).until(() -> fleet.edge.pollStats().failed() >= failedBefore + 3);
        assertThat(fleet.sink.of(DeviceUnreachable.class)).hasSize(1);

        SimAdmin.clear(fleet.sim, "robot2");
        await().atMost(DEADLINE).until(() -> fleet.edge.provider("robot2").orElseThrow().status() == ResourceStatus.OK);
        assertThat(fleet.sink.of(DeviceRecovered.class)).singleElement().satisfies(e -> assertThat(e.deviceId)
                .isEqualTo("robot2"));
        assertThat(fleet.edge.resource("robot2", "position", "x").orElseThrow().status()).isEqualTo(ResourceStatus.OK);
    }
}
