package eu.brain.iot.warehouse.integration;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import com.fasterxml.jackson.databind.JsonNode;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.world.MapParser;
import eu.brain.iot.robotsim.world.WarehouseMap;

/**
 * Two robots meet head-on in a corridor ({@code corridor.map}): with the orchestrator, the robot without a cart
 * steps aside and both errands complete with no deadlock counted; without it (its bundle stopped), robot-sim's own
 * rules leave them deadlocked (its deadlock counter), which is the case the orchestrator exists for.
 */
class CorridorIntegrationTest {

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 10_000)
    ConfigurationAdmin cm;

    @InjectService(timeout = 10_000)
    DeviceModel model;

    private static SimConfig corridor() throws Exception {
        try (InputStream in = CorridorIntegrationTest.class.getResourceAsStream("/corridor.map")) {
            WarehouseMap map = MapParser.parse("corridor.map", new String(in.readAllBytes(), StandardCharsets.UTF_8));
            return Warehouse.config(map);
        }
    }

    private Bundle orchestrator() {
        for (Bundle b : context.getBundles()) {
            if ("eu.brain.iot.behaviours.orchestrator".equals(b.getSymbolicName())) {
                return b;
            }
        }
        throw new AssertionError("no orchestrator bundle");
    }

    @Test
    void theOrchestratorResolvesAHeadOnMeeting() throws Exception {
        try (Warehouse w = new Warehouse(context, cm, model, corridor())) {
            JsonNode world = w.until("both carts in storage", 60, Warehouse::cartsInStorage);
            assertThat(world.get("counters").get("deadlocks").asLong()).as(Warehouse.describe(world)).isZero();
            assertThat(world.get("counters").get("nearMisses").asLong()).as("they did meet").isPositive();
            assertThat(w.outcomes).as("robot1 stepped aside: its go-to cancelled")
                    .anyMatch(o -> "CancelMissionCommand".equals(o.command) && "robot1".equals(o.deviceId));
        }
    }

    @Test
    void withoutTheOrchestratorTheyStayDeadlocked() throws Exception {
        Bundle orchestrator = orchestrator();
        try (Warehouse w = new Warehouse(context, cm, model, corridor())) {
            orchestrator.stop();
            JsonNode world = w.until("a deadlock counted", 60,
                    x -> x.get("counters").get("deadlocks").asLong() > 0);
            assertThat(Warehouse.cartsInStorage(world)).as(Warehouse.describe(world)).isFalse();
        } finally {
            orchestrator.start();
        }
    }
}
