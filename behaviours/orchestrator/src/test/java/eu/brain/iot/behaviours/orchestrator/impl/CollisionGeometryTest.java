package eu.brain.iot.behaviours.orchestrator.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.annotation.Annotation;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;

/**
 * A robot stopped behind a robot parked in its way: without the traffic planner the parked robot is sent aside by a
 * go-to of the orchestrator's own; under the planner nothing is sent (every go-to is a leg of a reserved path).
 */
class CollisionGeometryTest {

    private static final String MAP = String.join("\n",
            "##########",
            "#........#",
            "#........#",
            "#........#",
            "##########");

    private final Model model = new Model();
    private final Bus bus = new Bus();

    CollisionGeometryTest() {
        model.robot("robot1", 2, 2, "stopped", 1, "running", 8, 2); // on a go-to east, robot2 in front
        model.robot("robot2", 3, 2, "stopped", 0, null, 0, 0); // parked: no mission
    }

    @Test
    void aRobotParkedInTheWayIsSentAsideWithoutTheTrafficPlanner() {
        CollisionGeometry geometry = new CollisionGeometry(model, bus, mode(false));

        double resolved = geometry.resolve("robot1", 2);

        assertThat(resolved).as("the robot behind waits, then goes on").isEqualTo(2);
        assertThat(bus.sent).singleElement().isInstanceOfSatisfying(GoToCommand.class, go -> {
            assertThat(go.deviceId).isEqualTo("robot2");
            assertThat(go.y).as("off the row robot1 drives along").isNotEqualTo(2);
        });
    }

    @Test
    void underTheTrafficPlannerTheOrchestratorSendsNoRobotAnywhere() {
        CollisionGeometry geometry = new CollisionGeometry(model, bus, mode(true));

        double resolved = geometry.resolve("robot1", 2);

        assertThat(resolved).as("the robot behind waits: the planner pushes the parked one or plans around it")
                .isEqualTo(2);
        assertThat(bus.sent).isEmpty();
    }

    private static FleetMode mode(boolean traffic) {
        return new FleetMode() {
            @Override
            public boolean traffic() {
                return traffic;
            }

            @Override
            public Class<? extends Annotation> annotationType() {
                return FleetMode.class;
            }
        };
    }

    /** The commands the orchestrator publishes. */
    private static final class Bus implements EventBus {
        final List<BrainIoTEvent> sent = new CopyOnWriteArrayList<>();

        @Override
        public void deliver(BrainIoTEvent event) {
            sent.add(event);
        }

        @Override
        public void deliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException();
        }

        @Override
        public boolean tryDeliver(BrainIoTEvent event) {
            deliver(event);
            return true;
        }

        @Override
        public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException();
        }
    }

    /** The edge's device model of the robots on {@link #MAP}, written by the test. */
    private static final class Model implements DeviceModel {
        private final Map<String, ProviderSnapshot> robots = new LinkedHashMap<>();

        void robot(String id, int x, int y, String state, int detect, String missionState, int goalX, int goalY) {
            Map<String, Map<String, ResourceValue>> services = new LinkedHashMap<>();
            services.put("position", Map.of("x", value(id, "position", "x", x), "y", value(id, "position", "y", y),
                    "area", value(id, "position", "area", 0), "heading", value(id, "position", "heading", "E")));
            services.put("state", Map.of("state", value(id, "state", "state", state),
                    "detect", value(id, "state", "detect", detect)));
            if (missionState != null) {
                services.put("mission", Map.of("type", value(id, "mission", "type", "goto"),
                        "state", value(id, "mission", "state", missionState), "id", value(id, "mission", "id", 1L),
                        "goalX", value(id, "mission", "goalX", goalX), "goalY", value(id, "mission", "goalY", goalY)));
            }
            robots.put(id, new ProviderSnapshot(id, "robot", ResourceStatus.OK, Instant.now(), null, services,
                    Map.of()));
        }

        private static ResourceValue value(String id, String service, String resource, Object v) {
            return new ResourceValue(id, service, resource, v, Instant.now(), ResourceStatus.OK);
        }

        @Override
        public List<ProviderSnapshot> providers() {
            return new ArrayList<>(robots.values());
        }

        @Override
        public Optional<ProviderSnapshot> provider(String providerId) {
            return Optional.ofNullable(robots.get(providerId));
        }

        @Override
        public Optional<ResourceValue> resource(String providerId, String service, String resource) {
            if ("warehouse".equals(providerId) && "map".equals(service) && "rows".equals(resource)) {
                return Optional.of(new ResourceValue("warehouse", "map", "rows", MAP, Instant.now(),
                        ResourceStatus.OK));
            }
            return Optional.empty();
        }

        @Override
        public Subscription subscribe(String providerId, String service, ResourceListener listener) {
            throw new UnsupportedOperationException();
        }

        @Override
        public CompletionStage<CommandOutcome> act(String providerId, String service, String action,
                Map<String, Object> parameters) {
            throw new UnsupportedOperationException();
        }
    }
}
