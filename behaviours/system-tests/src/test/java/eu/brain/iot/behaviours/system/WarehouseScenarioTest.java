package eu.brain.iot.behaviours.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.door.DoorSmartBehaviour;
import eu.brain.iot.behaviours.door.impl.DoorExterns;
import eu.brain.iot.behaviours.events.ConnectorCollisionResolved;
import eu.brain.iot.behaviours.events.ConnectorResolveCollision;
import eu.brain.iot.behaviours.events.ConnectorResolveCollisionOffer;
import eu.brain.iot.behaviours.events.ConnectorTypeDoor;
import eu.brain.iot.behaviours.events.DoorBehaviorClosed;
import eu.brain.iot.behaviours.events.RobotBehaviorFromUnloadObstacle;
import eu.brain.iot.behaviours.events.RobotBehaviorStorageToDocking;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadToStorage;
import eu.brain.iot.behaviours.events.TransitionFired;
import eu.brain.iot.behaviours.orchestrator.OrchestratorSmartBehaviour;
import eu.brain.iot.behaviours.orchestrator.impl.OrchestratorExterns;
import eu.brain.iot.behaviours.robot.RobotSmartBehaviour;
import eu.brain.iot.behaviours.robot.impl.RobotExterns;

/**
 * The generated robot, door and orchestrator behaviours, built from their .bip models at this build, driven by
 * events: the paper's scenarios (collision resolution over three robots, the door broadcast, carrying a cart).
 * The same events and assertions make the in-Felix test (see bip/README.md).
 */
class WarehouseScenarioTest {

    static final float IN_UNLOAD = 2;
    static final int IS_OBSTACLE = 4;
    static final int IS_DOOR = 5;
    static final int IN_FRONT_OF_CART = 6;

    private TestBus bus;
    private RobotSmartBehaviour robots;
    private DoorSmartBehaviour door;
    private OrchestratorSmartBehaviour orchestrator;
    private DoorExterns doorExterns;

    @BeforeEach
    void start() {
        start(Map.of());
    }

    private void start(Map<String, Object> config) {
        bus = new TestBus();
        doorExterns = new DoorExterns();
        robots = new RobotSmartBehaviour(bus, RobotExterns.withoutFleet(), config);
        door = new DoorSmartBehaviour(bus, doorExterns, config);
        orchestrator = new OrchestratorSmartBehaviour(bus, new OrchestratorExterns(), config);
        bus.register(robots);
        bus.register(door);
        bus.register(orchestrator);
        bus.drain();
    }

    private void status(BrainIoTEventFactory factory, String robot, float position, int detect) {
        bus.publish(factory.make(robot, position, detect));
    }

    interface BrainIoTEventFactory {
        eu.brain.iot.eventing.api.BrainIoTEvent make(String robot, float position, int detect);
    }

    private static final BrainIoTEventFactory UNLOAD_LOCATION = (r, p, d) -> {
        RobotBehaviorUnloadLocation e = new RobotBehaviorUnloadLocation();
        e.component = r;
        e.position = p;
        e.detect = d;
        return e;
    };

    private static final BrainIoTEventFactory OBSTACLE = (r, p, d) -> {
        RobotBehaviorFromUnloadObstacle e = new RobotBehaviorFromUnloadObstacle();
        e.component = r;
        e.position = p;
        e.detect = d;
        return e;
    };

    @Test
    void robotsStartDockedAndWaitForTheirPollAnswers() {
        for (String r : List.of("Robot1", "Robot2", "Robot3")) {
            assertThat(robots.placesOf(r)).containsExactly("START");
            assertThat(robots.dataOf(r)).containsEntry("position", 1.0).containsEntry("cart", 3);
        }
        assertThat(door.placesOf("DoorInstance")).containsExactly("START");
        assertThat(orchestrator.placesOf("Orchestrator1")).containsExactly("START");
    }

    @Test
    void aCollisionIsResolvedWithTheRobotsThatReportItWithoutWaitingForTheOthers() {
        for (String r : List.of("Robot1", "Robot2", "Robot3")) {
            status(UNLOAD_LOCATION, r, IN_UNLOAD, 0);
            assertThat(robots.placesOf(r)).containsExactly("UNLOAD");
        }
        // Robot1 alone reports a robot in front: the orchestrator takes part with it (define p4 (p1' p2' p3'))
        status(OBSTACLE, "Robot1", IN_UNLOAD, IS_OBSTACLE);
        List<ConnectorResolveCollision> fired = bus.published(ConnectorResolveCollision.class);
        assertThat(fired).hasSize(1);
        ConnectorResolveCollision rdv = fired.get(0);
        assertThat(rdv.connector).isEqualTo("Connector2");
        assertThat(rdv.participants).containsExactlyInAnyOrder("p1", "p4");
        // its down: the orchestrator receives Robot1's position, 0 (not concerned) for the others
        assertThat(List.of(rdv.p4Position1, rdv.p4Position2, rdv.p4Position3))
                .containsExactly((double) IN_UNLOAD, 0.0, 0.0);
        // the resolution is broadcast by the orchestrator; the robot waiting in ROBOT joins
        assertThat(bus.published(ConnectorCollisionResolved.class)).hasSize(1);
        assertThat(robots.placesOf("Robot1")).containsExactly("START");
        // without an edge the rule keeps the robot's position: it goes on once the way is clear
        assertThat(robots.dataOf("Robot1")).containsEntry("position", (double) IN_UNLOAD).containsEntry("detect", 0);
        assertThat(robots.placesOf("Robot2")).containsExactly("UNLOAD");
        assertThat(orchestrator.placesOf("Orchestrator1")).containsExactly("START");

        // two more, one after the other: each resolved at once
        status(OBSTACLE, "Robot2", IN_UNLOAD, IS_OBSTACLE);
        status(OBSTACLE, "Robot3", IN_UNLOAD, IS_OBSTACLE);
        assertThat(bus.published(ConnectorResolveCollision.class)).hasSize(3).extracting(r -> r.participants)
                .containsExactly(List.of("p1", "p4"), List.of("p2", "p4"), List.of("p3", "p4"));
        for (String r : List.of("Robot1", "Robot2", "Robot3")) {
            assertThat(robots.placesOf(r)).as(r).containsExactly("START");
        }
        assertThat(orchestrator.dataOf("Orchestrator1")).containsEntry("collisions", 3);
    }

    @Test
    void aRobotAtTheDoorBroadcastsAndTheDoorOpensIfItIsReady() {
        status(UNLOAD_LOCATION, "Robot1", IN_UNLOAD, 0);
        status(OBSTACLE, "Robot1", IN_UNLOAD, IS_DOOR);
        ConnectorTypeDoor broadcast = bus.published(ConnectorTypeDoor.class).get(0);
        assertThat(broadcast.connector).isEqualTo("Connector1");
        assertThat(broadcast.initiator).isEqualTo("p2");
        assertThat(robots.placesOf("Robot1")).containsExactly("START");
        assertThat(door.placesOf("DoorInstance")).containsExactly("OPEN");
        assertThat(doorExterns.openings()).isEqualTo(1);

        // the door is open: a second robot's broadcast fires without it (the trigger never waits)
        status(UNLOAD_LOCATION, "Robot3", IN_UNLOAD, 0);
        status(OBSTACLE, "Robot3", IN_UNLOAD, IS_DOOR);
        assertThat(bus.published(ConnectorTypeDoor.class)).extracting(e -> e.initiator).containsExactly("p2", "p3");
        assertThat(robots.placesOf("Robot3")).containsExactly("START");
        assertThat(doorExterns.openings()).isEqualTo(1);

        DoorBehaviorClosed closed = new DoorBehaviorClosed();
        closed.component = "DoorInstance";
        bus.publish(closed);
        assertThat(door.placesOf("DoorInstance")).containsExactly("START");
    }

    @Test
    void aDetectedCartIsLiftedAndCarriedToStorage() {
        status(UNLOAD_LOCATION, "Robot2", IN_UNLOAD, 0);
        status(OBSTACLE, "Robot2", IN_UNLOAD, IN_FRONT_OF_CART);
        assertThat(robots.placesOf("Robot2")).containsExactly("UNLOAD");
        assertThat(robots.dataOf("Robot2")).containsEntry("cart", 2).containsEntry("carrying", true);
        RobotBehaviorUnloadToStorage toStorage = new RobotBehaviorUnloadToStorage();
        toStorage.component = "Robot2";
        toStorage.position = 3;
        bus.publish(toStorage);
        assertThat(robots.placesOf("Robot2")).containsExactly("STORAGE");
        RobotBehaviorStorageToDocking toDocking = new RobotBehaviorStorageToDocking();
        toDocking.component = "Robot2";
        toDocking.position = 1;
        bus.publish(toDocking);
        // carts are left: the robot goes round again (placing the cart in storage ended its carrying)
        assertThat(robots.placesOf("Robot2")).containsExactly("START");
        assertThat(robots.dataOf("Robot2")).containsEntry("carrying", false);
    }

    @Test
    void eventsForPortsThatAreNotEnabledAreIgnored() {
        status(OBSTACLE, "Robot1", IN_UNLOAD, IS_OBSTACLE);
        assertThat(robots.placesOf("Robot1")).containsExactly("START");
        assertThat(bus.published(ConnectorResolveCollisionOffer.class)).isEmpty();
    }

    @Test
    void traceConfigurationPublishesEveryTransition() {
        start(Map.of("trace", true));
        status(UNLOAD_LOCATION, "Robot1", IN_UNLOAD, 0);
        List<TransitionFired> trace = bus.published(TransitionFired.class);
        assertThat(trace).filteredOn(t -> t.component.equals("Robot1")).extracting(t -> t.port + ":" + t.from + "->" + t.to)
                .containsExactly("initial:[]->[START]", "unloadLocation:[START]->[UNLOAD]");
    }
}
