package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/** Which devices may change hands without interrupting anything: parked, idle, empty robots and closed doors. */
class RestingTest {

    @Test
    void aRobotParkedIdleAndEmptyInTheDockingAreaIsAtRest() {
        assertThat(Resting.atRest(robot(ResourceStatus.OK, 1, "finished", null))).isTrue();
        assertThat(Resting.atRest(robot(ResourceStatus.OK, 1, null, null))).as("no mission yet").isTrue();
        assertThat(Resting.atRest(robot(ResourceStatus.OK, 1, "failed", null))).isTrue();
    }

    @Test
    void aRobotWithWorkACartElsewhereOrNotPolledLatelyIsNot() {
        assertThat(Resting.atRest(robot(ResourceStatus.OK, 1, "running", null))).isFalse();
        assertThat(Resting.atRest(robot(ResourceStatus.OK, 1, "queued", null))).isFalse();
        assertThat(Resting.atRest(robot(ResourceStatus.OK, 1, "finished", "cart1"))).isFalse();
        assertThat(Resting.atRest(robot(ResourceStatus.OK, 0, "finished", null))).as("in a corridor").isFalse();
        assertThat(Resting.atRest(robot(ResourceStatus.STALE, 1, "finished", null))).isFalse();
        assertThat(Resting.atRest(robot(ResourceStatus.UNREACHABLE, 1, "finished", null))).isFalse();
    }

    @Test
    void aDoorIsAtRestClosedOnly() {
        assertThat(Resting.atRest(door("closed"))).isTrue();
        assertThat(Resting.atRest(door("opening"))).isFalse();
        assertThat(Resting.atRest(door("open"))).isFalse();
        assertThat(Resting.atRest(door("closing"))).isFalse();
    }

    private static ProviderSnapshot robot(ResourceStatus status, int area, String mission, String cart) {
        Map<String, Map<String, ResourceValue>> services = new HashMap<>();
        put(services, "robot1", "position", "area", area);
        put(services, "robot1", "mission", "state", mission);
        put(services, "robot1", "cart", "cart", cart);
        return new ProviderSnapshot("robot1", "robot", status, Instant.now(), null, services, Map.of());
    }

    private static ProviderSnapshot door(String state) {
        Map<String, Map<String, ResourceValue>> services = new HashMap<>();
        put(services, "door1", "door", "state", state);
        return new ProviderSnapshot("door1", "door", ResourceStatus.OK, Instant.now(), null, services, Map.of());
    }

    private static void put(Map<String, Map<String, ResourceValue>> services, String id, String service,
            String resource, Object value) {
        services.computeIfAbsent(service, k -> new HashMap<>()).put(resource,
                new ResourceValue(id, service, resource, value, Instant.now(), ResourceStatus.OK));
    }
}
