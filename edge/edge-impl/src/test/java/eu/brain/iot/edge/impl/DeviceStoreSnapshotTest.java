package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;

/**
 * The device model's snapshots are kept between writes and built again after every one ({@link DeviceStore#snapshot},
 * {@link DeviceStore#snapshots}): a reader never sees a value older than the last write that ended before it read.
 * The test's thread is the only writer.
 */
class DeviceStoreSnapshotTest {

    private final DeviceStore store = new DeviceStore(new ModelChanges() {
        @Override
        public void answered(String providerId, DeviceAnswer before, DeviceAnswer now, Instant at) {
        }

        @Override
        public void unreachable(String providerId, DeviceKind kind, String reason, int failures) {
        }

        @Override
        public void recovered(String providerId, DeviceKind kind, long downMillis) {
        }

        @Override
        public void moved(String providerId) {
        }

        @Override
        public void removed(String providerId, DeviceKind kind, String reason) {
        }
    });

    private static RobotAnswer robotAt(String id, int x, int y) {
        return new RobotAnswer(id, x, y, "N", 1, "stopped", 0, null, null, 0, 0);
    }

    private ProviderSnapshot robot(String id) {
        return store.snapshot(id).orElseThrow();
    }

    private static Object x(ProviderSnapshot p) {
        return p.services().get("position").get("x").value();
    }

    @Test
    void aSnapshotIsKeptUntilTheNextWriteAndShowsEveryWrite() {
        store.add("robot1", DeviceKind.ROBOT);
        Instant first = Instant.parse("2026-11-28T10:00:00Z");
        store.update("robot1", robotAt("robot1", 2, 4), first);
        ProviderSnapshot before = robot("robot1");
        assertThat(x(before)).isEqualTo(2);
        assertThat(robot("robot1")).as("no write in between: the same snapshot").isSameAs(before);

        store.update("robot1", robotAt("robot1", 3, 4), first.plusMillis(500));
        assertThat(x(robot("robot1"))).isEqualTo(3);

        Instant later = first.plusSeconds(1);
        store.unchanged("robot1", later);
        assertThat(robot("robot1").lastPoll()).isEqualTo(later);

        store.stale("robot1", "HTTP 503");
        assertThat(robot("robot1").status()).isEqualTo(ResourceStatus.STALE);
        assertThat(robot("robot1").services().get("position").get("x").status()).isEqualTo(ResourceStatus.STALE);

        store.unreachable("robot1", "HTTP 503: robot robot1 is offline", 3);
        assertThat(robot("robot1").status()).isEqualTo(ResourceStatus.UNREACHABLE);

        store.moved("robot1", "fleet.url changed");
        assertThat(robot("robot1").services()).isEmpty();
    }

    @Test
    void theListOfSnapshotsFollowsProvidersAddedAndRemovedInOrderOfTheirIds() {
        store.add("robot2", DeviceKind.ROBOT);
        store.add("robot1", DeviceKind.ROBOT);
        assertThat(store.snapshots()).extracting(ProviderSnapshot::id).containsExactly("robot1", "robot2");

        store.add("door1", DeviceKind.DOOR);
        assertThat(store.snapshots()).extracting(ProviderSnapshot::id).containsExactly("door1", "robot1", "robot2");

        store.remove("robot1", "left the fleet");
        assertThat(store.snapshots()).extracting(ProviderSnapshot::id).containsExactly("door1", "robot2");

        store.update("robot2", robotAt("robot2", 7, 1), Instant.now());
        assertThat(x(store.snapshots().get(1))).isEqualTo(7);
    }
}
