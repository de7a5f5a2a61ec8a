package eu.brain.iot.dashboard;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

class ActivityTest {

    private final Activity activity = new Activity(2);
    private final Devices devices = new Devices(activity);

    @Test
    void countsCommandsOnceWhetherTheCommandOrItsOutcomeComesFirst() {
        activity.event("eu.brain.iot.edge.api.GoToCommand", Map.of("commandId", "c1", "deviceId", "robot1", "x", 9,
                "y", 7), devices);
        activity.event("eu.brain.iot.edge.api.CommandOutcome", Map.of("commandId", "c1", "deviceId", "robot1",
                "command", "GoToCommand", "accepted", true), devices);
        activity.event("eu.brain.iot.edge.api.CommandOutcome", Map.of("commandId", "c2", "deviceId", "robot2",
                "command", "GoToCommand", "accepted", false, "reason", "goal (0,0) is a wall"), devices);

        assertThat(activity.counters()).containsEntry("commandsSent", 2L).containsEntry("commandsRefused", 1L);
        assertThat(activity.decisions()).extracting(d -> d.get("commandId") + ":" + d.get("outcome"))
                .containsExactly("c1:accepted", "c2:refused");
        assertThat(activity.decisions().get(0)).containsEntry("params", Map.of("x", 9, "y", 7));
    }

    @Test
    void keepsTheLastDecisionsOnly() {
        for (String id : new String[] { "a", "b", "c" }) {
            activity.event("eu.brain.iot.edge.api.OpenDoorCommand", Map.of("commandId", id, "deviceId", "door1"),
                    devices);
        }
        assertThat(activity.decisions()).extracting(d -> d.get("commandId")).containsExactly("b", "c");
        assertThat(activity.counters()).containsEntry("commandsSent", 3L);
    }

    @Test
    void countsCartsDeliveredToStorageObstaclesAndDoorOpenings() {
        set("robot1", "position", "area", 3);
        set("door1", "door", "state", "closed");
        set("door1", "door", "state", "opening");
        set("door1", "door", "state", "open");
        activity.event("eu.brain.iot.edge.api.CartPlaced", Map.of("robotId", "robot1", "cartId", "cart1"), devices);
        set("robot1", "position", "area", 2);
        activity.event("eu.brain.iot.edge.api.CartPlaced", Map.of("robotId", "robot1", "cartId", "cart2"), devices);
        activity.event("eu.brain.iot.edge.api.ObstacleDetected", Map.of("robotId", "robot1", "kind", "ROBOT"),
                devices);
        activity.event("eu.brain.iot.edge.api.ObstacleCleared", Map.of("robotId", "robot1", "kind", "ROBOT"), devices);
        activity.event("eu.brain.iot.edge.api.ObstacleDetected", Map.of("robotId", "robot1", "kind", "DOOR"), devices);

        assertThat(activity.counters()).containsEntry("cartsDelivered", 1L).containsEntry("doorOpenings", 1L)
                .containsEntry("robotInFront", 1L).containsEntry("robotInFrontResolved", 1L)
                .containsEntry("doorInFront", 1L);
    }

    @Test
    void sendsOnlyTheResourcesThatChangedOfAProviderItAlreadySent() {
        set("robot1", "position", "x", 1);
        devices.takeChanged();
        set("robot1", "position", "x", 2);

        assertThat(devices.takeChanged()).singleElement().satisfies(d -> {
            assertThat(d).containsEntry("id", "robot1").doesNotContainKey("full");
            assertThat(d.get("values")).isEqualTo(Map.of("position", Map.of("x", 2)));
        });
        assertThat(devices.hasChanges()).isFalse();
    }

    private void set(String provider, String service, String resource, Object value) {
        devices.apply(new ResourceValue(provider, service, resource, value, Instant.now(), ResourceStatus.OK));
    }
}
