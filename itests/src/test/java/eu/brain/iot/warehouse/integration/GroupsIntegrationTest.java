package eu.brain.iot.warehouse.integration;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import com.fasterxml.jackson.databind.JsonNode;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.robotsim.world.MapGenerator;

/**
 * Two groups of Listing 4 in Felix: a generated warehouse with six robots (robot1..3 are group g1, robot4..6 group
 * g2), six carts and one door, driven by the generated behaviours until every cart is in storage and every robot
 * docked, judged on robot-sim's ground truth: every robot of both groups carried carts (each group's instances act
 * for their own robots), no deadlock counted, every command accepted.
 */
class GroupsIntegrationTest {

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 10_000)
    ConfigurationAdmin cm;

    @InjectService(timeout = 10_000)
    DeviceModel model;

    @Test
    void twoGroupsOfRobotsCompleteTheWarehouse() throws Exception {
        try (Warehouse w = new Warehouse(context, cm, model,
                Warehouse.config(MapGenerator.generate(24, 14, 6, 6, 1, 7)))) {
            JsonNode world = w.until("every cart in storage, every robot docked", 120,
                    x -> Warehouse.cartsInStorage(x) && Warehouse.robotsDocked(x));
            assertThat(world.get("counters").get("deadlocks").asLong()).as(Warehouse.describe(world)).isZero();
            assertThat(w.outcomes).as("outcomes of the behaviours' commands").isNotEmpty()
                    .allSatisfy(o -> assertThat(o.accepted).as(o.command + " to " + o.deviceId + ": " + o.reason)
                            .isTrue());
            assertThat(w.outcomes.stream().filter(o -> "PickCartCommand".equals(o.command)).map(o -> o.deviceId))
                    .as("robots of both groups lifted carts").hasSize(6)
                    .anyMatch(r -> r.matches("robot[123]")).anyMatch(r -> r.matches("robot[456]"));
        }
    }
}
