package eu.brain.iot.edge.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.awaitility.Awaitility.await;

import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.RobotEvent;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.fault.FaultSettings;
import eu.brain.iot.robotsim.view.RobotView;

/**
 * The edge bundle on the real event bus in Felix, against robot-sim over real HTTP: what it polls reaches
 * behaviours as events; command events from behaviours move robots and doors; a configuration change through
 * Config Admin takes effect in place; a robot that goes offline is reported once and recovers.
 */
class EdgeBusIntegrationTest {

    @InjectBundleContext
    BundleContext context;
    @InjectService(timeout = 5_000)
    ConfigurationAdmin configurationAdmin;
    @InjectService(timeout = 5_000)
    EventBus bus;
    @InjectService(timeout = 5_000)
    DeviceModel model;

    private EdgeTestSupport edge;
    private RobotSim sim;
    private ServiceRegistration<?> recorderRegistration;
    private final List<BrainIoTEvent> received = new CopyOnWriteArrayList<>();

    @BeforeEach
    void start() throws Exception {
        Hashtable<String, Object> recorder = new Hashtable<>();
        recorder.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { RobotEvent.class.getName(),
                DoorStateChanged.class.getName(), DeviceUnreachable.class.getName(),
                DeviceRecovered.class.getName(), CommandOutcome.class.getName() });
        SmartBehaviour<BrainIoTEvent> behaviour = received::add;
        recorderRegistration = context.registerService(SmartBehaviour.class.getName(), behaviour, recorder);
        edge = EdgeTestSupport.start(context, configurationAdmin, model);
        sim = edge.sim;
    }

    /** Polls every 100 ms, gives up on an answer after 500 ms, reports after 2 failures, backs off up to 400 ms. */
    private void configure(String... robots) throws Exception {
        edge.configure(EdgeTestSupport.EDGE_PID, Map.of("fleet.url", sim.baseUri().toString(), "robots", robots,
                "poll.period.ms", 100L, "request.timeout.ms", 500L, "unreachable.after.failures", 2,
                "backoff.max.ms", 400L));
    }

    @AfterEach
    void stop() throws Exception {
        recorderRegistration.unregister();
        edge.close();
    }

    private <E extends BrainIoTEvent> List<E> received(Class<E> type) {
        return received.stream().filter(type::isInstance).map(type::cast).toList();
    }

    private boolean fleetIsUp() {
        List<ProviderSnapshot> providers = model.providers();
        return providers.size() == 4 && providers.stream().allMatch(p -> p.status() == ResourceStatus.OK);
    }

    @Test
    void everyRobotsPositionReachesBehavioursOnTheBus() {
        // the edge announces a robot's first position when it is first seen: here, on the new fleet URL
        await().atMost(DEADLINE).until(() -> received(RobotPositionChanged.class).stream().map(e -> e.robotId)
                .distinct().count() == 3);
        for (RobotPositionChanged e : received(RobotPositionChanged.class)) {
            RobotView r = sim.robot(e.robotId);
            assertThat(e.x + "," + e.y).as(e.robotId).isEqualTo(r.x() + "," + r.y());
            assertThat(e.sourceNode).as("filled in by the bus").isNotNull();
        }
    }

    @Test
    void commandEventsMoveARobotAndTheDoor() {
        await().atMost(DEADLINE).until(this::fleetIsUp);
        OpenDoorCommand open = new OpenDoorCommand();
        open.deviceId = "door1";
        open.commandId = "open-1";
        bus.deliver(open);
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot3";
        go.commandId = "go-1";
        go.x = 9;
        go.y = 4;
        bus.deliver(go);
        await().atMost(DEADLINE).until(() -> received(CommandOutcome.class).size() == 2);
        assertThat(received(CommandOutcome.class)).allSatisfy(o -> assertThat(o.accepted).as(o.reason).isTrue())
                .extracting(o -> o.commandId).containsExactlyInAnyOrder("open-1", "go-1");

        sim.step(10);
        await().atMost(DEADLINE).until(() -> received(RobotPositionChanged.class).stream()
                .anyMatch(e -> e.robotId.equals("robot3") && e.x == 9 && e.y == 4));
        await().atMost(DEADLINE).until(() -> received(DoorStateChanged.class).stream()
                .anyMatch(e -> e.state.equals("open")));
        assertThat(model.resource("door1", "door", "state").orElseThrow().value()).isEqualTo("open");
    }

    @Test
    void aNewConfigurationTakesEffectWithoutARestart() throws Exception {
        await().atMost(DEADLINE).until(this::fleetIsUp);
        configure("robot2");
        await().atMost(DEADLINE).until(() -> model.providers().stream().map(ProviderSnapshot::id).toList()
                .equals(List.of("robot2")));
        configure();
        await().atMost(DEADLINE).until(this::fleetIsUp);
    }

    @Test
    void aRobotThatGoesOfflineIsReportedOnceAndComesBack() throws Exception {
        configure();
        await().atMost(DEADLINE).until(this::fleetIsUp);
        sim.faults().setOwn(0, new FaultSettings(0, 0, 0, 0, true)); // robot1: the first robot of the map
        await().atMost(DEADLINE).until(() -> !received(DeviceUnreachable.class).isEmpty());
        assertThat(received(DeviceUnreachable.class)).singleElement().satisfies(e -> {
            assertThat(e.deviceId).isEqualTo("robot1");
            assertThat(e.reason).contains("offline");
        });
        sim.faults().clear();
        await().atMost(DEADLINE).until(() -> received(DeviceRecovered.class).size() == 1);
        assertThat(received(DeviceUnreachable.class)).hasSize(1);
    }
}
