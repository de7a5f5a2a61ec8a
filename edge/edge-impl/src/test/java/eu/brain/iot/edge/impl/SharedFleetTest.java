package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceReport;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.view.RobotView;

/**
 * Two nodes' edges share the paper's fleet (node1: 1/2, robot2 and the door; node2: 2/2, robot1 and robot3) over real
 * HTTP, their device reports carried to each other as the fabric carries them: each model shows the whole fleet, each
 * device with its owner, and a command published on either node is performed by the owner only.
 */
class SharedFleetTest {

    private static final Duration DEADLINE = Duration.ofSeconds(15);

    /** Keeps a node's events and hands its device reports to the other node's edge, as the fabric does. */
    private static final class FabricSink implements EventSink {
        final RecordingSink recorded = new RecordingSink();
        final AtomicReference<Edge> other = new AtomicReference<>();

        /** For each robot position this node published: the position, then where the other node's model had it. */
        final List<String> positionsSeenThere = new CopyOnWriteArrayList<>();

        @Override
        public boolean offer(BrainIoTEvent event) {
            Edge to = other.get();
            if (event instanceof DeviceReport r && to != null) {
                to.reported(r);
            }
            if (event instanceof RobotPositionChanged p && p.previousX != null && to != null) {
                positionsSeenThere.add(p.robotId + " at " + p.x + "," + p.y + ", there " + p.robotId + " at "
                        + to.resource(p.robotId, "position", "x").map(v -> v.value()).orElse(null) + ","
                        + to.resource(p.robotId, "position", "y").map(v -> v.value()).orElse(null));
            }
            return recorded.offer(event);
        }
    }

    private RobotSim sim;
    private final FabricSink sink1 = new FabricSink();
    private final FabricSink sink2 = new FabricSink();
    private Edge node1;
    private Edge node2;

    private FleetSettings share(String share) {
        return FleetSettings.of(sim.baseUri().toString(), List.of(), List.of(), 100, 1000, 8, 1, 2, 400)
                .withShare(Share.parse(share, 1));
    }

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        node1 = new Edge(share("1/2"), "node1", sink1, EdgeLog.stderr());
        node2 = new Edge(share("2/2"), "node2", sink2, EdgeLog.stderr());
        sink1.other.set(node2);
        sink2.other.set(node1);
    }

    @AfterEach
    void stop() {
        for (AutoCloseable c : new AutoCloseable[] { node1, node2, sim }) {
            try {
                if (c != null) {
                    c.close();
                }
            } catch (Exception e) {
                // closing the others still
            }
        }
    }

    private static String owner(ProviderSnapshot p) {
        var fabric = p.services().get(RemoteDevices.FABRIC_SERVICE);
        return fabric == null ? "here" : (String) fabric.get(RemoteDevices.OWNER_RESOURCE).value();
    }

    private void awaitWholeFleetOnBoth() {
        for (Edge e : List.of(node1, node2)) {
            await("the whole fleet in the model").atMost(DEADLINE).until(() -> e.providers().size() == 4
                    && e.providers().stream().allMatch(p -> p.status() == ResourceStatus.OK));
        }
    }

    @Test
    void eachNodeShowsTheWholeFleetEachDeviceWithItsOwner() {
        awaitWholeFleetOnBoth();

        assertThat(node1.providers()).extracting(SharedFleetTest::owner)
                .containsExactly("here", "node2", "here", "node2"); // door1, robot1, robot2, robot3
        assertThat(node2.providers()).extracting(SharedFleetTest::owner)
                .containsExactly("node1", "here", "node1", "here");
        assertThat(node1.resource("robot1", "position", "x")).map(v -> v.value())
                .isEqualTo(node2.resource("robot1", "position", "x").map(v -> v.value()));
    }

    @Test
    void aCommandIsPerformedByTheOwnerOnlyWhereverItWasPublished() {
        awaitWholeFleetOnBoth();
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot1"; // node2's
        go.commandId = "c-1";
        go.x = 9; // a free cell of the paper's map
        go.y = 7;

        Optional<CompletableFuture<CommandOutcome>> onPublisher = node1.execute(go, true);
        Optional<CompletableFuture<CommandOutcome>> onOwner = node2.execute(go, false);

        assertThat(onPublisher).as("node1 leaves it to robot1's owner").isEmpty();
        CommandOutcome outcome = onOwner.orElseThrow().join();
        assertThat(outcome.accepted).as(outcome.reason).isTrue();
        assertThat(sim.commandOrigins().robots().get("robot1").node()).isEqualTo("node2");
        assertThat(sink1.recorded.of(CommandOutcome.class)).isEmpty();
    }

    /**
     * A robot that moves is reported on its own before the event of its move: when the other node hears of the move,
     * its model shows the robot where the event says (with only the report every period, it showed the cell before).
     */
    @Test
    void aRobotThatMovedIsReportedToTheOtherNodeAheadOfTheEventOfItsMove() {
        awaitWholeFleetOnBoth();
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot1"; // node2's
        go.commandId = "c-4";
        go.x = 2; // straight down from its dock (2,1): robot2 stands east of it
        go.y = 4;
        assertThat(node2.execute(go, false).orElseThrow().join().accepted).isTrue();

        // one step at a time, each once its owner's edge has polled the last: every cell of the way is an event
        await("robot1 moved three times").atMost(DEADLINE).until(() -> {
            if (ownerShowsWhereTheSimHas("robot1")) {
                sim.step(1);
            }
            return sink2.positionsSeenThere.size() >= 3;
        });
        assertThat(sink2.positionsSeenThere).allSatisfy(seen -> {
            String[] halves = seen.split(", there ");
            assertThat(halves[1]).as(seen).isEqualTo(halves[0]);
        });
    }

    private boolean ownerShowsWhereTheSimHas(String robot) {
        RobotView truth = sim.robot(robot);
        return String.valueOf(truth.x()).equals(node2.resource(robot, "position", "x").map(v -> String.valueOf(
                v.value())).orElse(null)) && String.valueOf(truth.y()).equals(node2.resource(robot, "position", "y")
                        .map(v -> String.valueOf(v.value())).orElse(null));
    }

    @Test
    void aParkedIdleRobotAndAClosedDoorAreAtRestOnTheirOwnerOnlyAndARobotOnAMissionIsNot() {
        awaitWholeFleetOnBoth();
        assertThat(node2.atRest("robot1")).as("docked, idle, empty").isTrue();
        assertThat(node1.atRest("door1")).as("closed").isTrue();
        assertThat(node1.atRest("robot1")).as("node2's").isFalse();
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot1";
        go.commandId = "c-5";
        go.x = 2; // straight down from its dock (2,1)
        go.y = 4;
        assertThat(node2.execute(go, false).orElseThrow().join().accepted).isTrue();
        await("robot1 on its mission, as its owner shows it").atMost(DEADLINE).until(() -> !node2.atRest("robot1"));
    }

    @Test
    void aCommandFromAnotherNodeForADeviceThisNodeDoesNotHaveHasNoOutcomeHere() {
        awaitWholeFleetOnBoth();
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot7";
        go.commandId = "c-2";

        assertThat(node2.execute(go, false)).isEmpty();
        assertThat(node2.execute(new GoToCommand(), false)).as("no deviceId: refused on its publisher only").isEmpty();
        CommandOutcome unknown = node1.execute(go, true).orElseThrow().join();
        assertThat(unknown.accepted).isFalse();
        assertThat(unknown.reason).startsWith("unknown device 'robot7'");
    }

    @Test
    void aDeviceWhoseOwnerStoppedReportingIsStaleAndItsCommandsAreRefusedOnThePublisher() {
        awaitWholeFleetOnBoth();
        node2.close();

        await("robot1 stale on node1").atMost(DEADLINE).until(() -> node1.provider("robot1")
                .map(p -> p.status() == ResourceStatus.STALE).orElse(false));
        assertThat(node1.provider("robot1").orElseThrow().reason())
                .startsWith("node node2 has not reported robot1 for");
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot1";
        go.commandId = "c-3";
        CommandOutcome refused = node1.execute(go, true).orElseThrow().join();
        assertThat(refused.accepted).isFalse();
        assertThat(refused.reason).startsWith("no node owns robot1 now: node node2, which owned it, has not reported it");
        assertThat(sim.commandOrigins().robots()).doesNotContainKey("robot1");
    }

    @Test
    void aFleetNotSharedReportsNothing() throws Exception {
        try (Edge alone = new Edge(FleetSettings.of(sim.baseUri().toString(), List.of(), List.of(), 100, 1000, 8, 1,
                2, 400), "node3", sink1.recorded, EdgeLog.stderr())) {
            await().atMost(DEADLINE).until(() -> alone.providers().size() == 4);
            CommandOutcome o = alone.execute(new GoToCommand(), true).orElseThrow().join();
            assertThat(o.accepted).isFalse(); // no deviceId: performed (and refused) here, as on one node
        }
        assertThat(sink1.recorded.of(DeviceReport.class)).allMatch(r -> "node1".equals(r.node));
    }
}
