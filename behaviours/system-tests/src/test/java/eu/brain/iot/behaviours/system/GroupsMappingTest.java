package eu.brain.iot.behaviours.system;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.door.DoorSmartBehaviour;
import eu.brain.iot.behaviours.door.DoorBehaviorExterns;
import eu.brain.iot.behaviours.events.ConnectorResolveCollision;
import eu.brain.iot.behaviours.events.ConnectorTypeDoor;
import eu.brain.iot.behaviours.events.RobotBehaviorFromUnloadObstacle;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation;
import eu.brain.iot.behaviours.orchestrator.OrchestratorSmartBehaviour;
import eu.brain.iot.behaviours.orchestrator.OrchestratorBehaviorExterns;
import eu.brain.iot.behaviours.robot.RobotSmartBehaviour;
import eu.brain.iot.behaviours.robot.RobotBehaviorExterns;
import eu.brain.iot.behaviours.warehouse.ModelInstance;
import eu.brain.iot.behaviours.warehouse.RobotNames;

/**
 * How the fleet's robots map to the groups of the generated behaviours (robotK is {@code Robot<(K-1)%3+1>} of
 * {@code g<ceil(K/3)>}), and that the extern functions, told the instance by {@code bipInstance}, act for the right
 * fleet robot: the robot, door and orchestrator behaviours on a test bus with two groups, one of them with a single
 * robot (robot31 of a 31-robot fleet), whose collision the subset rendezvous resolves without the missing robots.
 */
class GroupsMappingTest {

    @Test
    void everyRobotHasOneComponentOfOneGroupAndBack() {
        assertThat(RobotNames.group(1)).isEqualTo("g1");
        assertThat(RobotNames.component(1)).isEqualTo("Robot1");
        assertThat(RobotNames.group(5)).isEqualTo("g2");
        assertThat(RobotNames.component(5)).isEqualTo("Robot2");
        assertThat(RobotNames.group(30)).isEqualTo("g10");
        assertThat(RobotNames.component(30)).isEqualTo("Robot3");
        assertThat(RobotNames.group(31)).isEqualTo("g11");
        assertThat(RobotNames.component(31)).isEqualTo("Robot1");
        for (int k = 1; k <= 100; k++) {
            String robot = "robot" + k;
            assertThat(RobotNames.robotId(RobotNames.group(k), RobotNames.component(k))).isEqualTo(robot);
            assertThat(RobotNames.inGroup(robot, RobotNames.group(k))).isTrue();
            assertThat(RobotNames.inGroup(robot, RobotNames.group(k + 3))).isFalse();
        }
        assertThat(RobotNames.robotId("", 2)).as("the default group is read as g1").isEqualTo("robot2");
        assertThat(RobotNames.robotId(null, 3)).isEqualTo("robot3");
        assertThat(RobotNames.number("door1")).isEqualTo(-1);
        assertThatThrownBy(() -> RobotNames.robotId("west", 1)).hasMessageContaining("\"west\" is not of the form gN");
        assertThatThrownBy(() -> RobotNames.robotId("g0", 1)).hasMessageContaining("\"g0\" is not of the form gN");
    }

    @Test
    void theInstanceIsKeptPerThread() throws InterruptedException {
        ModelInstance instance = new ModelInstance();
        instance.set("g4", "Robot2");
        assertThat(instance.robotId(2)).isEqualTo("robot11");
        String[] other = new String[1];
        Thread t = new Thread(() -> other[0] = instance.robotId(2));
        t.start();
        t.join();
        assertThat(other[0]).as("another thread named no instance: the default group").isEqualTo("robot2");
    }

    /** Records, per extern call, the fleet robot it is for. */
    static final class Recording implements RobotBehaviorExterns, OrchestratorBehaviorExterns, DoorBehaviorExterns {
        final ModelInstance instance = new ModelInstance();
        final List<String> calls = new ArrayList<>();

        @Override
        public void bipInstance(String group, String component) {
            instance.set(group, component);
        }

        @Override
        public double getPosition(int robotId) {
            return 1;
        }

        @Override
        public void moveTo(int robotId, double position) {
            calls.add("moveTo " + instance.robotId(robotId));
        }

        @Override
        public int liftCart(int robotId, int remaining) {
            calls.add("liftCart " + instance.robotId(robotId));
            return remaining - 1;
        }

        @Override
        public void placeCart(int robotId) {
            calls.add("placeCart " + instance.robotId(robotId));
        }

        @Override
        public double resolvedPosition1(double p) {
            return resolved(1, p);
        }

        @Override
        public double resolvedPosition2(double p) {
            return resolved(2, p);
        }

        @Override
        public double resolvedPosition3(double p) {
            return resolved(3, p);
        }

        private double resolved(int k, double p) {
            if (p != 0) {
                calls.add("resolve " + instance.robotId(k));
            }
            return p;
        }

        @Override
        public void open(int requests) {
            calls.add("open for " + instance.group());
        }
    }

    @Test
    void eachGroupDrivesItsOwnRobotsAndAGroupWithOneRobotResolvesItsCollisions() {
        TestBus bus = new TestBus();
        Recording externs = new Recording();
        RobotSmartBehaviour robots = new RobotSmartBehaviour(bus, externs, Map.of());
        OrchestratorSmartBehaviour orchestrator = new OrchestratorSmartBehaviour(bus, externs, Map.of());
        DoorSmartBehaviour door = new DoorSmartBehaviour(bus, externs, Map.of());
        bus.register(robots);
        bus.register(orchestrator);
        bus.register(door);
        bus.drain();

        // robot5 (g2/Robot2) and robot31 (g11/Robot1, its group's only robot) set off
        publish(bus, unloadLocation(5));
        publish(bus, unloadLocation(31));
        assertThat(robots.groups()).contains("g2", "g11").doesNotContain("g1");
        assertThat(robots.placesOf("g2", "Robot2")).containsExactly("UNLOAD");
        assertThat(robots.placesOf("g2", "Robot1")).containsExactly("START");
        assertThat(robots.placesOf("g11", "Robot1")).containsExactly("UNLOAD");
        assertThat(externs.calls).containsExactly("moveTo robot5", "moveTo robot31");

        // robot31 is stopped behind a robot: g11's orchestrator resolves it alone (robot32, robot33 do not exist)
        externs.calls.clear();
        publish(bus, obstacle(31, WarehouseScenarioTest.IS_OBSTACLE));
        List<ConnectorResolveCollision> fired = bus.published(ConnectorResolveCollision.class);
        assertThat(fired).hasSize(1);
        assertThat(fired.get(0).group).isEqualTo("g11");
        assertThat(fired.get(0).participants).containsExactlyInAnyOrder("p1", "p4");
        assertThat(externs.calls).containsExactly("resolve robot31", "moveTo robot31");
        assertThat(robots.placesOf("g2", "Robot2")).as("another group is not concerned").containsExactly("UNLOAD");
        assertThat(orchestrator.groups()).contains("g11").doesNotContain("g2");

        // robot5 at the closed door: g2's door model opens it, for g2
        externs.calls.clear();
        publish(bus, obstacle(5, WarehouseScenarioTest.IS_DOOR));
        assertThat(bus.published(ConnectorTypeDoor.class)).extracting(e -> e.group).containsExactly("g2");
        assertThat(externs.calls).containsExactly("open for g2");
        assertThat(door.placesOf("g2", "DoorInstance")).containsExactly("OPEN");
        assertThat(door.placesOf("g11", "DoorInstance")).isNull();
    }

    private static void publish(TestBus bus, eu.brain.iot.eventing.api.BrainIoTEvent e) {
        bus.publish(e);
    }

    private static RobotBehaviorUnloadLocation unloadLocation(int k) {
        RobotBehaviorUnloadLocation e = new RobotBehaviorUnloadLocation();
        e.group = RobotNames.group(k);
        e.component = RobotNames.component(k);
        e.position = WarehouseScenarioTest.IN_UNLOAD;
        return e;
    }

    private static RobotBehaviorFromUnloadObstacle obstacle(int k, int detect) {
        RobotBehaviorFromUnloadObstacle e = new RobotBehaviorFromUnloadObstacle();
        e.group = RobotNames.group(k);
        e.component = RobotNames.component(k);
        e.position = WarehouseScenarioTest.IN_UNLOAD;
        e.detect = detect;
        return e;
    }
}
