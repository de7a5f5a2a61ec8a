package eu.brain.iot.bip.generate;

import static eu.brain.iot.bip.generate.GeneratedWarehouse.call;
import static eu.brain.iot.bip.generate.GeneratedWarehouse.field;
import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;


/**
 * Groups (bip/README.md, "Groups"): the generated warehouse behaviours host one copy of Listing 4's root compound per
 * group named by events; groups progress independently, a rendezvous and a broadcast stay within their group, the
 * default group behaves as without groups, and the number of groups is bounded with one clear error per refused group.
 */
class GroupsTest {

    private static final String EVENTS = "eu.brain.iot.behaviours.events.";
    private static final String ROBOTS = "eu.brain.iot.behaviours.robot.RobotSmartBehaviour";
    private static final double IN_UNLOAD = 2;
    private static final int IS_OBSTACLE = 4;
    private static final int IS_DOOR = 5;

    private static Toolchain tool;

    private GeneratedWarehouse bus;
    private Object robots;
    private Object door;
    private Object orchestrator;

    @BeforeAll
    static void generate() {
        tool = Tools.warehouse();
        assertThat(tool.diagnostics().errors()).isEmpty();
    }

    private void start(Map<String, Object> config, Path dir) throws Exception {
        bus = new GeneratedWarehouse(tool, null, dir);
        robots = bus.start(ROBOTS, "eu.brain.iot.behaviours.robot.RobotBehaviorExterns", config);
        door = bus.start("eu.brain.iot.behaviours.door.DoorSmartBehaviour",
                "eu.brain.iot.behaviours.door.DoorBehaviorExterns", config);
        orchestrator = bus.start("eu.brain.iot.behaviours.orchestrator.OrchestratorSmartBehaviour",
                "eu.brain.iot.behaviours.orchestrator.OrchestratorBehaviorExterns", config);
    }

    private void unload(String group, String robot) throws Exception {
        bus.publish(EVENTS + "RobotBehaviorUnloadLocation", group, "component", robot, "position", IN_UNLOAD,
                "detect", 0);
    }

    private void obstacle(String group, String robot, int detect) throws Exception {
        bus.publish(EVENTS + "RobotBehaviorFromUnloadObstacle", group, "component", robot, "position", IN_UNLOAD,
                "detect", detect);
    }

    private static Object places(Object behaviour, String group, String component) {
        return call(behaviour, "placesOf", group, component);
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> data(Object behaviour, String method, Object... args) {
        return (Map<String, Object>) call(behaviour, method, args);
    }

    @Test
    void twoGroupsProgressIndependentlyAndTheDefaultGroupIsUntouched(@TempDir Path dir) throws Exception {
        start(Map.of(), dir);
        for (String r : List.of("Robot1", "Robot2", "Robot3")) {
            unload("A", r);
        }
        unload("B", "Robot2");
        for (String r : List.of("Robot1", "Robot2", "Robot3")) {
            assertThat(places(robots, "A", r)).isEqualTo(List.of("UNLOAD"));
            assertThat(places(robots, "B", r)).isEqualTo(List.of(r.equals("Robot2") ? "UNLOAD" : "START"));
            assertThat(call(robots, "placesOf", r)).as("default group").isEqualTo(List.of("START"));
        }
        assertThat(call(robots, "groups")).isEqualTo(List.of("", "A", "B"));
        assertThat(data(robots, "dataOf", "A", "Robot1")).containsEntry("id", 1)
                .containsEntry("position", IN_UNLOAD);
        assertThat(places(robots, "C", "Robot1")).as("a group no event named").isNull();
        // a new group runs the initial transitions, and the externs are told which copy calls them
        assertThat(bus.calls).filteredOn(c -> c.function().equals("getPosition"))
                .extracting(c -> c.group() + "/" + c.component() + "/" + c.args())
                .containsExactly("/Robot1/[1]", "/Robot2/[2]", "/Robot3/[3]", "A/Robot1/[1]", "A/Robot2/[2]",
                        "A/Robot3/[3]", "B/Robot1/[1]", "B/Robot2/[2]", "B/Robot3/[3]");
    }

    @Test
    void aRendezvousTakesOffersOfItsOwnGroupOnly(@TempDir Path dir) throws Exception {
        start(Map.of(), dir);
        for (String g : List.of("A", "B")) {
            for (String r : List.of("Robot1", "Robot2", "Robot3")) {
                unload(g, r);
            }
        }
        obstacle("A", "Robot1", IS_OBSTACLE);
        obstacle("A", "Robot2", IS_OBSTACLE);
        obstacle("B", "Robot3", IS_OBSTACLE);
        // The deployed rendezvous (Warehouse.bip) is define p4 (p1' p2' p3'): the orchestrator takes any robots that
        // offered, with itself. Offers of p1, p2 (group A) and p3 (group B) together would make one interaction with
        // p3 in group A, or one of p1 p2 p3 p4: each group's orchestrator must take its own group's offers only.
        assertThat(bus.published(EVENTS + "ConnectorResolveCollisionOffer"))
                .extracting(o -> field(o, "group") + "/" + field(o, "component"))
                .containsExactly("A/Robot1", "A/Robot2", "B/Robot3");
        List<Object> fired = bus.published(EVENTS + "ConnectorResolveCollision");
        assertThat(fired).extracting(e -> field(e, "group") + ":" + field(e, "participants"))
                .containsExactlyInAnyOrder("A:[p1, p4]", "A:[p2, p4]", "B:[p3, p4]");
        assertThat(data(orchestrator, "dataOf", "A", "Orchestrator1")).containsEntry("collisions", 2);
        assertThat(data(orchestrator, "dataOf", "B", "Orchestrator1")).containsEntry("collisions", 1);
        assertThat(data(orchestrator, "dataOf", "Orchestrator1")).containsEntry("collisions", 0);
        assertThat(places(robots, "A", "Robot3")).as("A's Robot3 offered nothing: not taken by B's Robot3's offer")
                .isEqualTo(List.of("UNLOAD"));
        assertThat(bus.published(EVENTS + "ConnectorCollisionResolved")).extracting(e -> field(e, "group"))
                .containsExactlyInAnyOrder("A", "A", "B");
        assertThat(places(orchestrator, "A", "Orchestrator1")).isEqualTo(List.of("START"));
        assertThat(places(orchestrator, "B", "Orchestrator1")).isEqualTo(List.of("START"));
    }

    @Test
    void aBroadcastReachesTheDoorOfItsOwnGroupOnly(@TempDir Path dir) throws Exception {
        start(Map.of(), dir);
        unload("A", "Robot1");
        unload("B", "Robot1");
        bus.publish(EVENTS + "DoorBehaviorClosed", "B", "component", "DoorInstance"); // B's door exists (START)
        assertThat(call(door, "groups")).isEqualTo(List.of("", "B"));

        obstacle("A", "Robot1", IS_DOOR);
        assertThat(bus.published(EVENTS + "ConnectorTypeDoor")).extracting(e -> field(e, "group")).containsExactly("A");
        assertThat(places(door, "A", "DoorInstance")).isEqualTo(List.of("OPEN"));
        assertThat(places(door, "B", "DoorInstance")).isEqualTo(List.of("START"));
        assertThat(call(door, "placesOf", "DoorInstance")).isEqualTo(List.of("START"));
        assertThat(bus.calls).filteredOn(c -> c.function().equals("open"))
                .extracting(c -> c.group() + "/" + c.component()).containsExactly("A/DoorInstance");
    }

    @Test
    void theDefaultGroupIsNullOrEmptyAndPublishesNoGroup(@TempDir Path dir) throws Exception {
        start(Map.of(), dir);
        for (String r : List.of("Robot1", "Robot2", "Robot3")) {
            unload(r.equals("Robot2") ? "" : null, r);
        }
        obstacle(null, "Robot1", IS_OBSTACLE);
        obstacle("", "Robot2", IS_OBSTACLE);
        obstacle(null, "Robot3", IS_OBSTACLE);
        assertThat(call(robots, "groups")).isEqualTo(List.of(""));
        // each robot's report is taken at once (the subset rendezvous of Warehouse.bip), all in the default group
        assertThat(bus.published(EVENTS + "ConnectorResolveCollision")).hasSize(3)
                .allSatisfy(e -> assertThat(field(e, "group")).isNull());
        assertThat(bus.published(EVENTS + "ConnectorResolveCollisionOffer")).hasSize(3)
                .allSatisfy(e -> assertThat(field(e, "group")).isNull());
        assertThat(data(orchestrator, "dataOf", "Orchestrator1")).containsEntry("collisions", 3);
        assertThat(data(orchestrator, "dataOf", null, "Orchestrator1")).containsEntry("collisions", 3);
    }

    @Test
    void groupsBeyondMaxGroupsAreRefusedWithOneErrorEach(@TempDir Path dir) throws Exception {
        List<LogRecord> logged = new ArrayList<>();
        Handler handler = new Handler() {
            @Override
            public void publish(LogRecord r) {
                if (r.getLevel().intValue() >= Level.SEVERE.intValue()) {
                    logged.add(r);
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger logger = Logger.getLogger(ROBOTS);
        logger.addHandler(handler);
        try {
            start(Map.of("max.groups", "2"), dir);
            unload("A", "Robot1");
            unload("B", "Robot1");
            unload("B", "Robot2");
            unload("C", "Robot1");
            assertThat(call(robots, "groups")).isEqualTo(List.of("", "A"));
            assertThat(places(robots, "A", "Robot1")).isEqualTo(List.of("UNLOAD"));
            assertThat(places(robots, "B", "Robot1")).isNull();
            assertThat(logged).extracting(r -> java.text.MessageFormat.format(r.getMessage(), r.getParameters()))
                    .containsExactly(
                            "events of group \"B\" are refused: this behaviour already hosts max.groups=2 groups; "
                                    + "configure a larger max.groups (PID " + ROBOTS + ") to host more",
                            "events of group \"C\" are refused: this behaviour already hosts max.groups=2 groups; "
                                    + "configure a larger max.groups (PID " + ROBOTS + ") to host more");
        } finally {
            logger.removeHandler(handler);
        }
    }

    @Test
    void maxGroupsDefaultsTo1024AndTheConfigurationIsAPropertyType(@TempDir Path dir) throws Exception {
        start(Map.of("max.groups", "many"), dir);
        Class<?> config = bus.loader.loadClass(ROBOTS + "$Config");
        assertThat(config.isAnnotation()).isTrue();
        assertThat(config.getMethod("max_groups").getDefaultValue()).isEqualTo(GroupWriter.MAX_GROUPS);
        for (int g = 0; g < 40; g++) {
            unload("g" + g, "Robot1");
        }
        assertThat((List<?>) call(robots, "groups")).hasSize(41);
    }
}
