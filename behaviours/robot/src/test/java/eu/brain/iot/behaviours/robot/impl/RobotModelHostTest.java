package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.lang.reflect.Proxy;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.robot.RobotSmartBehaviour;

/**
 * A node hosts the model instances of the robots it owns: an input for one of them fires the port on the node's model
 * and is answered by a report of the instance's places, data and steps; an input for a robot the node does not own
 * changes nothing; every owned robot is reported without an input too, so that the instance driving the fleet knows
 * it.
 */
class RobotModelHostTest {

    private static final Duration DEADLINE = Duration.ofSeconds(20);

    private final FleetLeadershipTest.Recorded bus = new FleetLeadershipTest.Recorded();
    private final RobotExterns externs = new RobotExterns();
    private final RobotSmartBehaviour model = new RobotSmartBehaviour(bus, externs, Map.of());
    /** node2 of a fleet of six robots owns robot1 and robot4. */
    private final FleetLeadershipTest.Ownership ownership = new FleetLeadershipTest.Ownership("node2",
            Set.of("robot1", "robot4", "door1"), Set.of("robot1", "robot2", "robot3", "robot4", "robot5", "robot6",
                    "door1"));
    /** node2's instance, which hears of no other: it drives the fleet once it has listened for a while. */
    private final FleetLeadership leadership = new FleetLeadership(new FleetLeadershipTest.Recorded(), ownership,
            null);
    private final RobotModelHost host = new RobotModelHost(bus, ownership, leadership, model, externs, defaults(),
            null);

    @AfterEach
    void stop() throws InterruptedException {
        host.deactivate();
        leadership.deactivate();
    }

    private static RobotConfig defaults() {
        return (RobotConfig) Proxy.newProxyInstance(RobotConfig.class.getClassLoader(),
                new Class<?>[] { RobotConfig.class }, (proxy, method, args) -> method.getDefaultValue());
    }

    private static RobotModelInput input(String robot, long seq, ModelPort port, double position) {
        RobotModelInput in = new RobotModelInput();
        in.coordinator = "leader";
        in.node = "node2";
        in.robotId = robot;
        in.seq = seq;
        in.port = port.name();
        in.position = position;
        return in;
    }

    private List<RobotModelReport> reports(String robot) {
        return bus.events.stream().filter(RobotModelReport.class::isInstance).map(RobotModelReport.class::cast)
                .filter(r -> robot.equals(r.robot)).toList();
    }

    @Test
    void anOwnedRobotsInputFiresItsPortAndIsAnsweredWithItsPlacesDataAndSteps() {
        host.notify(input("robot4", 7, ModelPort.UNLOAD_LOCATION, 2));
        await().atMost(DEADLINE).until(() -> reports("robot4").stream().anyMatch(r -> r.seq == 7));
        RobotModelReport r = reports("robot4").stream().filter(x -> x.seq == 7).findFirst().orElseThrow();
        assertThat(r.node).isEqualTo("node2");
        assertThat(r.coordinator).isEqualTo("leader");
        assertThat(r.places).containsExactly("UNLOAD");
        assertThat(r.steps).containsExactly("MOVE_ON");
        assertThat(ModelMirror.data(r.data)).containsEntry("cart", 3L).containsEntry("carrying", false)
                .containsEntry("position", 2.0);
        assertThat(model.placesOf("g2", "Robot1")).containsExactly("UNLOAD");
    }

    @Test
    void anotherNodesRobotsInputChangesNothing() {
        host.notify(input("robot2", 1, ModelPort.UNLOAD_LOCATION, 2));
        host.notify(input("robot4", 2, ModelPort.UNLOAD_LOCATION, 2)); // after it, on the host's thread
        await().atMost(DEADLINE).until(() -> reports("robot4").stream().anyMatch(r -> r.seq == 2));
        assertThat(reports("robot2")).isEmpty();
        assertThat(model.placesOf("g1", "Robot2")).as("robot2's instance").isNull();
        assertThat(externs.takeSteps("robot2")).isEmpty();
    }

    @Test
    void theHostTakesTheInputsNamingItsNode() {
        assertThat(RobotModelHost.properties("node2").get("eu.brain.iot.behaviour.filter")).isEqualTo("(node=node2)");
        assertThat(RobotModelHost.escaped("a(b)*\\")).isEqualTo("a\\28b\\29\\2a\\5c");
        assertThat((String[]) RobotModelHost.properties("node2").get("eu.brain.iot.behaviour.consumed"))
                .containsExactly(RobotModelInput.class.getName());
    }

    @Test
    void everyOwnedRobotIsReportedWithoutAnInputOnceAnInstanceDrivesTheFleetAndOnlyRobots() {
        assertThat(leadership.leaderId()).as("it listens first").isNull();
        assertThat(bus.events).as("no report before an instance drives the fleet").isEmpty();
        await().atMost(DEADLINE).until(() -> !reports("robot1").isEmpty() && !reports("robot4").isEmpty());
        assertThat(leadership.leaderId()).isEqualTo(leadership.instanceId());
        assertThat(reports("robot1").get(0).places).as("no instance yet: its group is not created").isEmpty();
        assertThat(reports("robot1").get(0).seq).isEqualTo(-1);
        assertThat(bus.events.stream().filter(RobotModelReport.class::isInstance)
                .map(e -> ((RobotModelReport) e).robot)).containsOnly("robot1", "robot4");
        int before = reports("robot1").size();
        await().atMost(DEADLINE).until(() -> reports("robot1").size() > before); // once a second
    }
}
