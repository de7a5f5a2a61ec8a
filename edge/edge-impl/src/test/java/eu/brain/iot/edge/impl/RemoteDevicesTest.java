package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.DeviceReport;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/** The devices other nodes report: the newest poll wins, own reports and own devices are not taken, stale ones say so. */
class RemoteDevicesTest {

    private final AtomicLong nanos = new AtomicLong(1_000_000_000L);
    private final RemoteDevices remote = new RemoteDevices("node1", 2_500, nanos::get);

    private static ProviderSnapshot robot(String id, int x, long lastPollMillis) {
        Instant at = Instant.ofEpochMilli(lastPollMillis);
        Map<String, Map<String, ResourceValue>> services = new TreeMap<>();
        services.put("position", Map.of("x", new ResourceValue(id, "position", "x", x, at, ResourceStatus.OK),
                "heading", new ResourceValue(id, "position", "heading", "N", at, ResourceStatus.OK)));
        services.put("mission", Map.of("id", new ResourceValue(id, "mission", "id", 7_000_000_000L, at,
                ResourceStatus.OK)));
        return new ProviderSnapshot(id, "robot", ResourceStatus.OK, at, null, services, DeviceKind.ROBOT.actions);
    }

    private static DeviceReport report(String node, ProviderSnapshot... devices) {
        DeviceReport r = new DeviceReport();
        r.node = node;
        r.devices = new ArrayList<>(RemoteDevices.encode(List.of(devices)));
        return r;
    }

    @Test
    void aReportedDeviceShowsWithItsValuesAndItsOwner() {
        remote.accept(report("node2", robot("robot2", 4, 1000)), id -> false);

        ProviderSnapshot p = remote.snapshot("robot2").orElseThrow();
        assertThat(p.kind()).isEqualTo("robot");
        assertThat(p.status()).isEqualTo(ResourceStatus.OK);
        assertThat(p.services().get("position").get("x").value()).isEqualTo(4);
        assertThat(p.services().get("mission").get("id").value()).isEqualTo(7_000_000_000L);
        assertThat(p.services().get(RemoteDevices.FABRIC_SERVICE).get(RemoteDevices.OWNER_RESOURCE).value())
                .isEqualTo("node2");
        assertThat(p.actions()).isEqualTo(DeviceKind.ROBOT.actions);
        assertThat(remote.owner("robot2")).contains("node2");
    }

    @Test
    void theNewestPollWinsWhicheverNodeSentIt() {
        remote.accept(report("node3", robot("robot2", 5, 2000)), id -> false);
        remote.accept(report("node2", robot("robot2", 4, 1000)), id -> false); // the old owner's last, late

        assertThat(remote.snapshot("robot2").orElseThrow().services().get("position").get("x").value()).isEqualTo(5);
        assertThat(remote.owner("robot2")).contains("node3");
    }

    @Test
    void ownReportsAndOwnDevicesAreNotTaken() {
        remote.accept(report("node1", robot("robot1", 1, 1000)), id -> false);
        remote.accept(report("node2", robot("robot3", 1, 1000)), id -> id.equals("robot3"));

        assertThat(remote.snapshots()).isEmpty();
    }

    @Test
    void aDeviceNotReportedForLongerThanAllowedIsStaleAndNamesItsLastOwner() {
        remote.accept(report("node2", robot("robot2", 4, 1000)), id -> false);
        nanos.addAndGet(3_000_000_000L);

        ProviderSnapshot p = remote.snapshot("robot2").orElseThrow();
        assertThat(p.status()).isEqualTo(ResourceStatus.STALE);
        assertThat(p.reason()).isEqualTo("node node2 has not reported robot2 for 3000 ms");
        assertThat(p.services().get("position").get("x").status()).isEqualTo(ResourceStatus.STALE);
        assertThat(remote.owner("robot2")).isEmpty();
        assertThat(remote.lastOwner("robot2")).contains("node2");
    }

    @Test
    void malformedEntriesAreSkippedAndCountedTheRestTaken() {
        DeviceReport r = report("node2", robot("robot2", 4, 1000));
        r.devices.add(Map.of("id", "robot9", "kind", "forklift", "values", Map.of()));
        r.devices.add(Map.of("id", "../etc", "kind", "robot", "values", Map.of()));
        r.devices.add(Map.of("id", "robot8", "kind", "robot", "values", "not a map"));

        assertThat(remote.accept(r, id -> false)).isEqualTo(3);
        assertThat(remote.malformed()).isEqualTo(3);
        assertThat(remote.snapshots()).extracting(ProviderSnapshot::id).containsExactly("robot2");
    }

    @Test
    void onlyRobotsAndDoorsAreReported() {
        ProviderSnapshot cart = new ProviderSnapshot("cart1", "cart", ResourceStatus.OK, null, null, Map.of(),
                Map.of());
        assertThat(RemoteDevices.encode(List.of(cart, robot("robot1", 1, 1000)))).extracting(m -> m.get("id"))
                .containsExactly("robot1");
    }
}
