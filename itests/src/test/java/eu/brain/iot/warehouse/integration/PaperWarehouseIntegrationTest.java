package eu.brain.iot.warehouse.integration;

import static org.assertj.core.api.Assertions.assertThat;


import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import com.fasterxml.jackson.databind.JsonNode;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.fault.FaultSettings;
import eu.brain.iot.robotsim.world.WarehouseMap;

/**
 * The paper's warehouse end to end in Felix: robot-sim (3 robots, 3 carts, one door) over real HTTP, the edge, and
 * the robot, door and orchestrator behaviours generated from their BIP models drive the fleet until every cart is
 * in storage and every robot back in docking, judged on robot-sim's ground truth ({@code GET /world}): REQ-1 (every
 * cart carried to storage), REQ-2 (no cycle of robots waiting on each other for 10 s of warehouse time: robot-sim's
 * deadlock counter with 20 steps stays 0), and every command the behaviours sent accepted.
 */
class PaperWarehouseIntegrationTest {

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 10_000)
    ConfigurationAdmin cm;

    @InjectService(timeout = 10_000)
    DeviceModel model;

    @Test
    void everyCartReachesStorageAndEveryRobotItsDock() throws Exception {
        try (Warehouse w = new Warehouse(context, cm, model, Warehouse.config(WarehouseMap.paper()))) {
            JsonNode world = w.until("every cart in storage, every robot docked", 90,
                    x -> Warehouse.cartsInStorage(x) && Warehouse.robotsDocked(x));
            assertThat(world.get("counters").get("deadlocks").asLong()).as(Warehouse.describe(world)).isZero();
            assertThat(w.outcomes).as("outcomes of the behaviours' commands").isNotEmpty()
                    .allSatisfy(o -> assertThat(o.accepted).as(o.command + " to " + o.deviceId + ": " + o.reason)
                            .isTrue());
            assertThat(w.outcomes.stream().filter(o -> "PickCartCommand".equals(o.command)).count()).isEqualTo(3);
            assertThat(w.outcomes.stream().filter(o -> "PlaceCartCommand".equals(o.command)).count()).isEqualTo(3);
            assertThat(w.outcomes.stream().map(o -> o.command)).contains("OpenDoorCommand");
        }
    }

    /**
     * A robot goes offline while it carries a cart (robot-sim's fault API): the edge reports it unreachable, the
     * binding leaves it alone, the others go on (stopped behind it, they wait); once it answers again it finishes
     * its errand where it was, and the warehouse completes.
     */
    @Test
    void aRobotOfflineMidErrandFinishesItAfterItRecovers() throws Exception {
        try (Warehouse w = new Warehouse(context, cm, model, Warehouse.config(WarehouseMap.paper()))) {
            JsonNode carrying = w.until("a robot carries a cart", 60, x -> carrier(x) != null);
            String robot = carrier(carrying);
            int index = Integer.parseInt(robot.substring("robot".length())) - 1;
            w.sim.faults().setOwn(index, new FaultSettings(0, 0, 0, 0, true));
            org.awaitility.Awaitility.await("the edge reports " + robot + " unreachable")
                    .atMost(java.time.Duration.ofSeconds(20))
                    .until(() -> model.provider(robot).orElseThrow().status() == ResourceStatus.UNREACHABLE);
            JsonNode during = w.world();
            w.sim.faults().setOwn(index, null); // it follows the fleet again: no fault
            JsonNode world = w.until("every cart in storage, every robot docked", 90,
                    x -> Warehouse.cartsInStorage(x) && Warehouse.robotsDocked(x));
            assertThat(Warehouse.cartsInStorage(during)).as("not done while " + robot + " was offline").isFalse();
            assertThat(world.get("counters").get("deadlocks").asLong()).as(Warehouse.describe(world)).isZero();
        }
    }

    /** @return the robot carrying a cart in this world, or {@code null} */
    private static String carrier(JsonNode world) {
        for (JsonNode c : world.get("carts")) {
            if (!c.get("carriedBy").isNull()) {
                return c.get("carriedBy").asText();
            }
        }
        return null;
    }
}
