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
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.world.SimRules;
import eu.brain.iot.robotsim.world.WarehouseMap;

/**
 * The paper's warehouse end to end in Felix: robot-sim (3 robots, 3 carts, one door) over real HTTP, the edge, and
 * the robot, door and orchestrator behaviours generated from their BIP models drive the fleet until every cart is
 * in storage and every robot back in docking, judged on robot-sim's ground truth ({@code GET /world}): REQ-1 (every
 * cart carried to storage), REQ-2 (no cycle of robots waiting on each other for 10 s of warehouse time: robot-sim's
 * deadlock counter with 20 steps stays 0), and every command the behaviours sent accepted.
 */
class PaperWarehouseIntegrationTest {

    /** 20 steps per 0.5 s of wall time: the errands take about a minute of warehouse time, a few seconds here. */
    static final double SPEED = 20;

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 10_000)
    ConfigurationAdmin cm;

    @InjectService(timeout = 10_000)
    DeviceModel model;

    @Test
    void everyCartReachesStorageAndEveryRobotItsDock() throws Exception {
        SimConfig config = SimConfig.builder().map(WarehouseMap.paper()).speed(SPEED)
                .rules(new SimRules(1L, 2, 2, 20, -1)).build();
        try (Warehouse w = new Warehouse(context, cm, config)) {
            w.awaitEdge(model, 3, 3);
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
}
