package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceRemoved;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.view.RobotCommander;

/**
 * The edge core on node "node1" of two, against robot-sim over real HTTP: it polls its share only, takes and
 * releases devices at run time, and names its node on every command.
 */
class OwnershipTest {

    private static final Duration DEADLINE = Duration.ofSeconds(15);
    private final RecordingSink sink = new RecordingSink();
    private RobotSim sim;
    private Edge edge;

    /** Node 1 of 2 on the paper's warehouse: robot2 (2 mod 2 = 0) and door1 (doors.owner 1). */
    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(FleetSettings.of(sim.baseUri().toString(), List.of(), List.of(), 100, 1000, 8, 1, 2, 400)
                .withShare(Share.parse("1/2", 1)), "node1", sink, EdgeLog.stderr());
    }

    @AfterEach
    void stop() {
        try {
            edge.close();
        } finally {
            sim.close();
        }
    }

    private void awaitProviders(String... ids) {
        await("providers " + List.of(ids) + ", all OK").atMost(DEADLINE).untilAsserted(() -> {
            List<ProviderSnapshot> providers = edge.providers();
            assertThat(providers).extracting(ProviderSnapshot::id).containsExactly(ids);
            assertThat(providers).allSatisfy(p -> assertThat(p.status()).isEqualTo(ResourceStatus.OK));
        });
    }

    private CommandOutcome goTo(String robot, int x, int y) throws Exception {
        GoToCommand g = new GoToCommand();
        g.deviceId = robot;
        g.x = x;
        g.y = y;
        return edge.execute(g).get();
    }

    @Test
    void aNodePollsItsShareOnlyAndCommandsNothingElse() throws Exception {
        awaitProviders("door1", "robot2");
        assertThat(edge.ownership().owned()).containsExactly("door1", "robot2");
        assertThat(edge.ownership().owns("robot1")).isFalse();
        long sent = edge.pollStats().sent();
        Instant later = Instant.now().plusMillis(300);
        await().atMost(DEADLINE).until(() -> edge.providers().stream().allMatch(p -> p.lastPoll().isAfter(later)));
        // two devices polled every 100 ms: robot1 and robot3 never were (three or four would double the count)
        long polls = edge.pollStats().sent() - sent;
        long elapsedPeriods = Duration.between(later.minusMillis(300), Instant.now()).toMillis() / 100 + 2;
        assertThat(polls).as("polls of two devices in some %d periods", elapsedPeriods)
                .isLessThanOrEqualTo(2 * elapsedPeriods + 2);
        assertThat(sink.events).noneMatch(e -> e.toString().contains("robot1") || e.toString().contains("robot3"));
        assertThat(sink.of(RobotPositionChanged.class)).extracting(e -> e.robotId).containsOnly("robot2");
        CommandOutcome refused = goTo("robot1", 2, 4);
        assertThat(refused.accepted).isFalse();
        assertThat(refused.reason).contains("unknown device 'robot1'");
        assertThat(sim.commandOrigins().robots()).isEmpty();
    }

    @Test
    void everyCommandNamesTheNode() throws Exception {
        awaitProviders("door1", "robot2");
        assertThat(goTo("robot2", 4, 4).accepted).isTrue();
        RobotCommander c = sim.commandOrigins().robots().get("robot2");
        assertThat(c.node()).isEqualTo("node1");
        assertThat(c.commands()).isEqualTo(1);
    }

    @Test
    void aDeviceTakenMidErrandIsPolledAtOnceAnnouncedAndItsMissionEndTold() throws Exception {
        awaitProviders("door1", "robot2");
        // robot3 is on an errand another node gave it
        {
            int status = java.net.http.HttpClient.newHttpClient().send(java.net.http.HttpRequest.newBuilder(sim.baseUri().resolve(
                    "robot3/robot_local_control/NavigationComponent/GoToComponent/add"))
                    .header("Content-Type", "application/json").header("X-Brain-Node", "node2")
                    .POST(java.net.http.HttpRequest.BodyPublishers.ofString("{\"x\":6,\"y\":4}")).build(),
                    java.net.http.HttpResponse.BodyHandlers.discarding()).statusCode();
            assertThat(status).isEqualTo(200);
        }
        sim.step(1);
        Instant asked = Instant.now();
        assertThat(edge.ownership().take(Set.of("robot3", "robot2"))).as("robot2 was owned").containsExactly("robot3");
        awaitProviders("door1", "robot2", "robot3");
        // polled at once: well within one period of 100 ms on an idle machine; 1 s is room for a loaded one
        assertThat(edge.provider("robot3").orElseThrow().lastPoll()).isBefore(asked.plusSeconds(1));
        assertThat(sink.of(RobotPositionChanged.class, e -> e.robotId.equals("robot3"))).singleElement()
                .satisfies(e -> {
                    assertThat(e.previousX).as("announced as first seen").isNull();
                    assertThat(e.x + "," + e.y).isEqualTo(sim.robot("robot3").x() + "," + sim.robot("robot3").y());
                });
        sim.step(10);
        await("robot3's mission end told").atMost(DEADLINE).until(() -> !sink.of(MissionFinished.class,
                e -> e.robotId.equals("robot3")).isEmpty());
        assertThat(goTo("robot3", 6, 3).accepted).isTrue();
        assertThat(sim.commandOrigins().robots().get("robot3").node()).isEqualTo("node1");
        assertThat(sim.commandOrigins().changes()).singleElement().satisfies(c -> {
            assertThat(c.from()).isEqualTo("node2");
            assertThat(c.to()).isEqualTo("node1");
        });
    }

    @Test
    void aDeviceReleasedLeavesTheModelWithDeviceRemovedAndIsCommandedNoMore() throws Exception {
        awaitProviders("door1", "robot2");
        assertThat(edge.ownership().release(Set.of("robot2", "robot1"))).as("robot1 was not owned")
                .containsExactly("robot2");
        await("robot2 removed").atMost(DEADLINE).until(() -> !sink.of(DeviceRemoved.class).isEmpty());
        assertThat(sink.of(DeviceRemoved.class)).singleElement().satisfies(e -> {
            assertThat(e.deviceId).isEqualTo("robot2");
            assertThat(e.reason).contains("not owned by node node1");
        });
        assertThat(edge.providers()).extracting(ProviderSnapshot::id).containsExactly("door1");
        assertThat(edge.ownership().owned()).containsExactly("door1");
        assertThat(goTo("robot2", 4, 4).accepted).isFalse();
        // taken back: announced again as a first sight
        int before = sink.of(RobotPositionChanged.class).size();
        edge.ownership().take(Set.of("robot2"));
        awaitProviders("door1", "robot2");
        await().atMost(DEADLINE).until(() -> sink.of(RobotPositionChanged.class).size() > before);
        assertThat(sink.of(RobotPositionChanged.class).get(before).previousX).isNull();
    }

    @Test
    void aNewShareStartsAfreshAndBadIdsAreRefused() {
        awaitProviders("door1", "robot2");
        edge.ownership().take(Set.of("robot1"));
        awaitProviders("door1", "robot1", "robot2");
        edge.configure(FleetSettings.of(sim.baseUri().toString(), List.of(), List.of(), 100, 1000, 8, 1, 2, 400)
                .withShare(Share.parse("2/2", 1)));
        awaitProviders("robot1", "robot3");
        assertThatThrownBy(() -> edge.ownership().take(Set.of("robot 1"))).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("'robot 1' is no device id");
        assertThatThrownBy(() -> edge.ownership().release(null)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void aLeasedShareIsOwnedOnlyOnceTakenAndSaidAsTheShare() throws Exception {
        awaitProviders("door1", "robot2");
        edge.configure(FleetSettings.of(sim.baseUri().toString(), List.of(), List.of(), 100, 1000, 8, 1, 2, 400)
                .withShare(Share.parse("1/2", 1).withLeased(true)));
        await("the share leaves the model until it is leased").atMost(DEADLINE)
                .until(() -> edge.providers().stream().noneMatch(p -> p.id().startsWith("robot")));
        assertThat(edge.ownership().owned()).isEmpty();
        assertThat(edge.ownership().share()).containsExactly("door1", "robot2");
        assertThat(edge.ownership().fleet()).containsExactly("door1", "robot1", "robot2", "robot3");
        assertThat(goTo("robot2", 5, 3).accepted).as("not owned: not commanded").isFalse();

        edge.ownership().take(Set.of("robot2", "door1"));
        awaitProviders("door1", "robot2");
        assertThat(Share.parse("1/2", 1).withLeased(true)).hasToString("1/2 (doors on node 1), once leased");
    }
}
