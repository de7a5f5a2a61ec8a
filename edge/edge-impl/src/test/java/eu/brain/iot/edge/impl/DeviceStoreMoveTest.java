package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceRemoved;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * The device model when the edge moves to another fleet URL ({@link DeviceStore#moved}) and when a device leaves
 * ({@link DeviceStore#remove}), with the events derived from it ({@link EdgeEvents}): no HTTP, no fleet thread (the
 * test's thread is the only writer).
 */
class DeviceStoreMoveTest {

    private final RecordingSink bus = new RecordingSink();
    private final List<String> changes = new ArrayList<>();
    private final EdgeEvents events = new EdgeEvents(new Outbox(bus, EdgeLog.stderr()),
            new MissionTracker(new FleetApi(), Runnable::run, new Outbox(bus, EdgeLog.stderr()), EdgeLog.stderr()));
    private final DeviceStore store = new DeviceStore(new ModelChanges() {
        @Override
        public void answered(String providerId, DeviceAnswer before, DeviceAnswer now, Instant at) {
            changes.add("answered " + providerId + (before == null ? " first" : ""));
            events.answered(providerId, before, now, at);
        }

        @Override
        public void unreachable(String providerId, DeviceKind kind, String reason, int failures) {
            changes.add("unreachable " + providerId);
            events.unreachable(providerId, kind, reason, failures);
        }

        @Override
        public void recovered(String providerId, DeviceKind kind, long downMillis) {
            changes.add("recovered " + providerId);
            events.recovered(providerId, kind, downMillis);
        }

        @Override
        public void moved(String providerId) {
            changes.add("moved " + providerId);
            events.moved(providerId);
        }

        @Override
        public void removed(String providerId, DeviceKind kind, String reason) {
            changes.add("removed " + providerId);
            events.removed(providerId, kind, reason);
        }
    });
    private final List<ResourceValue> heard = new CopyOnWriteArrayList<>();

    private static RobotAnswer robot1At(int x, int y) {
        return new RobotAnswer("robot1", x, y, "N", 1, "stopped", 0, null, null, 0, 0);
    }

    private ProviderSnapshot robot1() {
        return store.snapshot("robot1").orElseThrow();
    }

    @Test
    void anUnreachableDeviceStaysSoWithoutTheOldFleetsValuesAndIsToldRecoveredWhenTheNewFleetAnswers() {
        store.add("robot1", DeviceKind.ROBOT);
        store.update("robot1", robot1At(2, 4), Instant.now());
        store.unreachable("robot1", "HTTP 503: robot robot1 is offline", 2);
        store.subscribe(null, null, heard::add);

        store.moved("robot1", "fleet.url changed to http://other/: waiting for its inventory (GET /)");
        assertThat(robot1().status()).isEqualTo(ResourceStatus.UNREACHABLE);
        assertThat(robot1().reason()).startsWith("fleet.url changed to http://other/").contains("unreachable since");
        assertThat(robot1().services()).as("the old fleet's values").isEmpty();
        assertThat(store.resource("robot1", "position", "x")).isEmpty();

        store.update("robot1", robot1At(2, 1), Instant.now());
        assertThat(robot1().status()).isEqualTo(ResourceStatus.OK);
        assertThat(store.resource("robot1", "position", "y").orElseThrow().value()).isEqualTo(1);
        assertThat(heard).as("every value of the new fleet reaches the listeners, OK")
                .anySatisfy(v -> assertThat(v.resource()).isEqualTo("y"))
                .allSatisfy(v -> assertThat(v.status()).isEqualTo(ResourceStatus.OK));
        assertThat(changes).containsExactly("answered robot1 first", "unreachable robot1", "moved robot1",
                "recovered robot1", "answered robot1 first");
        assertThat(bus.of(DeviceUnreachable.class)).hasSize(1);
        assertThat(bus.of(DeviceRecovered.class)).singleElement().satisfies(e -> assertThat(e.deviceId)
                .isEqualTo("robot1"));
        // announced afresh: where it stands in the new fleet, with no previous cell from the other fleet
        RobotPositionChanged last = bus.of(RobotPositionChanged.class).get(1);
        assertThat(last.y).isEqualTo(1);
        assertThat(last.previousX).isNull();
    }

    @Test
    void aDeviceThatAnsweredIsStaleUntilTheNewFleetAnswersAndIsNotToldRecovered() {
        store.add("robot1", DeviceKind.ROBOT);
        store.update("robot1", robot1At(2, 4), Instant.now());
        store.subscribe(null, null, heard::add);

        store.moved("robot1", "fleet.url changed to http://other/: not polled there yet");
        assertThat(robot1().status()).isEqualTo(ResourceStatus.STALE);
        assertThat(robot1().reason()).isEqualTo("fleet.url changed to http://other/: not polled there yet");
        assertThat(robot1().services()).isEmpty();
        assertThat(heard).as("listeners hear every resource go STALE").isNotEmpty()
                .allSatisfy(v -> assertThat(v.status()).isEqualTo(ResourceStatus.STALE));

        store.update("robot1", robot1At(2, 4), Instant.now());
        assertThat(robot1().status()).isEqualTo(ResourceStatus.OK);
        assertThat(bus.of(DeviceRecovered.class)).isEmpty();
        assertThat(bus.of(RobotPositionChanged.class)).as("the same cell, announced anew at the new fleet")
                .hasSize(2);
    }

    @Test
    void aRemovedRobotOrDoorIsToldWithItsReasonACartIsNot() {
        store.add("robot1", DeviceKind.ROBOT);
        store.add("door1", DeviceKind.DOOR);
        store.add("cart1", DeviceKind.CART);
        store.remove("robot1", "not in the fleet at http://other/ (GET / lists 2 robots, 1 doors)");
        store.remove("door1", "not in the configuration eu.brain.iot.edge any more (robots, doors)");
        store.remove("cart1", "not in the fleet's world any more");
        store.remove("robot9", "never there");

        assertThat(store.snapshots()).isEmpty();
        assertThat(changes).containsExactly("removed robot1", "removed door1", "removed cart1");
        assertThat(bus.of(DeviceRemoved.class)).extracting(e -> e.deviceId + " " + e.deviceKind + ": " + e.reason)
                .containsExactly("robot1 robot: not in the fleet at http://other/ (GET / lists 2 robots, 1 doors)",
                        "door1 door: not in the configuration eu.brain.iot.edge any more (robots, doors)");
    }
}
