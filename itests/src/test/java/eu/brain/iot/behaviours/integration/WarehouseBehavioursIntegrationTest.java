package eu.brain.iot.behaviours.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Collectors;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;
import org.osgi.test.common.annotation.Property;
import org.osgi.test.common.annotation.config.WithConfiguration;

import eu.brain.iot.behaviours.events.ConnectorCollisionResolved;
import eu.brain.iot.behaviours.events.ConnectorResolveCollision;
import eu.brain.iot.behaviours.events.RobotBehaviorFromUnloadObstacle;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation;
import eu.brain.iot.behaviours.events.TransitionFired;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The robot, door and orchestrator behaviours generated from their BIP models at this build, running as bundles
 * in Felix on the real bus: robots meet an obstacle in the unload area and the orchestrator resolves each one
 * through the rendezvous connector of the paper's Listing 7, with the robots that report (no waiting for all three).
 * The robot behaviour runs with {@code trace=true} (osgi-test's {@code @WithConfiguration}, removed again after
 * the tests).
 */
@WithConfiguration(pid = WarehouseBehavioursIntegrationTest.ROBOT_PID, location = "?", properties = @Property(key = "trace",
        value = "true", scalar = Property.Scalar.Boolean))
class WarehouseBehavioursIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(15);
    static final String ROBOT_PID = "eu.brain.iot.behaviours.robot.RobotSmartBehaviour";
    static final float IN_UNLOAD = 2;
    static final int IS_OBSTACLE = 4;

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 10_000)
    EventBus bus;

    @InjectService(timeout = 10_000)
    eu.brain.iot.eventing.monitoring.api.EventBusStatistics stats;

    final List<BrainIoTEvent> seen = new CopyOnWriteArrayList<>();

    @BeforeEach
    void traceTheRobotsAndRecord() throws Exception {
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { TransitionFired.class.getName(),
                ConnectorResolveCollision.class.getName(), ConnectorCollisionResolved.class.getName() });
        // through the test's CloseableBundleContext: unregistered when the test ends
        context.registerService(SmartBehaviour.class.getName(), (SmartBehaviour<BrainIoTEvent>) seen::add, props);
        // the reconfigured behaviour is up once its service carries the property
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(robotService("(trace=true)"))
                .as("the robot behaviour reconfigured with trace=true").isNotNull());
    }

    private ServiceReference<?> robotService(String filter) throws Exception {
        ServiceReference<?>[] refs = context.getServiceReferences(SmartBehaviour.class.getName(),
                "(&(component.name=" + ROBOT_PID + ")" + filter + ")");
        return refs == null ? null : refs[0];
    }

    private void publish(BrainIoTEvent event) {
        bus.deliver(event);
    }

    private static RobotBehaviorUnloadLocation atUnload(String robot) {
        RobotBehaviorUnloadLocation e = new RobotBehaviorUnloadLocation();
        e.component = robot;
        e.position = IN_UNLOAD;
        e.detect = 0;
        return e;
    }

    private static RobotBehaviorFromUnloadObstacle obstacle(String robot) {
        RobotBehaviorFromUnloadObstacle e = new RobotBehaviorFromUnloadObstacle();
        e.component = robot;
        e.position = IN_UNLOAD;
        e.detect = IS_OBSTACLE;
        return e;
    }

    private <T> List<T> seen(Class<T> type) {
        return seen.stream().filter(type::isInstance).map(type::cast).collect(Collectors.toList());
    }

    /** The places a robot went through, from its traced transitions (the initial one excluded). */
    private List<String> pathOf(String robot) {
        List<String> path = new ArrayList<>();
        for (TransitionFired t : seen(TransitionFired.class)) {
            if (robot.equals(t.component) && !"initial".equals(t.port) && !t.from.equals(t.to)) {
                if (path.isEmpty()) {
                    path.add(String.join("+", t.from));
                }
                path.add(String.join("+", t.to));
            }
        }
        return path;
    }

    private String describe() {
        return seen.stream().map(e -> e instanceof TransitionFired t
                ? t.component + ":" + t.port + " " + t.from + "->" + t.to
                : e.getClass().getSimpleName()).collect(Collectors.joining("; "))
                + " | consumers: " + stats.consumers().stream().map(c -> c.consumer + "/" + c.delivered + "/" + c.failures + c.consumed).collect(Collectors.joining(", "))
                + " | types: " + stats.eventTypes().stream().map(t -> t.eventType + " p=" + t.published + " d=" + t.delivered + " f=" + t.failed + " u=" + t.unhandled).collect(Collectors.joining(", "));
    }

    @Test
    void aRobotInFrontIsResolvedWithoutWaitingForTheOtherRobots() {
        for (String robot : List.of("Robot1", "Robot2", "Robot3")) {
            publish(atUnload(robot));
        }
        publish(obstacle("Robot1"));
        // the orchestrator takes part with the robots that report (define p4 (p1' p2' p3')): Robot1 alone
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(pathOf("Robot1")).as("Robot1's places; seen: %s",
                describe()).containsExactly("START", "UNLOAD", "OBSTACLE", "ROBOT", "START"));
        ConnectorResolveCollision first = seen(ConnectorResolveCollision.class).get(0);
        assertThat(first.connector).isEqualTo("Connector2");
        assertThat(first.participants).containsExactlyInAnyOrder("p1", "p4");
        assertThat(List.of(first.p4Position1, first.p4Position2, first.p4Position3))
                .containsExactly((double) IN_UNLOAD, 0.0, 0.0);
        assertThat(seen(ConnectorCollisionResolved.class)).hasSize(1);
        assertThat(pathOf("Robot2")).containsExactly("START", "UNLOAD");

        publish(obstacle("Robot2"));
        publish(obstacle("Robot3"));
        for (String robot : List.of("Robot2", "Robot3")) {
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(pathOf(robot)).as(robot)
                    .containsExactly("START", "UNLOAD", "OBSTACLE", "ROBOT", "START"));
        }
        // Robot2 and Robot3 together or one after the other, as their offers came: never Robot1 again
        List<ConnectorResolveCollision> all = seen(ConnectorResolveCollision.class);
        assertThat(all).hasSizeBetween(2, 3);
        assertThat(all.subList(1, all.size()))
                .allSatisfy(r -> assertThat(r.participants).doesNotContain("p1").contains("p4"));
    }

}
