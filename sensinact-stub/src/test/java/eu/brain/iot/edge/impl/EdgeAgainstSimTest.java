package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.ObstacleKind;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/** The edge core against the real simulator over real HTTP (no framework). */
class EdgeAgainstSimTest {

    private static final Duration DEADLINE = Duration.ofSeconds(10);

    private RobotSim sim;
    private Edge edge;
    private final RecordingSink sink = new RecordingSink();

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        edge = new Edge(settings(List.of(), List.of()), sink, EdgeLog.stderr());
    }

    @AfterEach
    void stop() {
        edge.close();
        sim.close();
    }

    private FleetSettings settings(List<String> robots, List<String> doors) {
        return FleetSettings.of(sim.baseUri().toString(), robots, doors, 100, 1000, 8, 1, 2, 400);
    }

    @Test
    void discoversTheFleetAndPublishesFirstPositions() {
        await().atMost(DEADLINE).until(() -> sink.of(RobotPositionChanged.class).size() >= 3);
        assertThat(edge.providers()).extracting(p -> p.id()).containsExactly("door1", "robot1", "robot2", "robot3");
        await().atMost(DEADLINE).until(() -> edge.providers().stream().allMatch(p -> p.status() == ResourceStatus.OK));
        var r3 = sim.robot("robot3");
        assertThat(edge.resource("robot3", "position", "x")).get().extracting(v -> v.value()).isEqualTo(r3.x());
        assertThat(edge.resource("door1", "door", "state")).get().extracting(v -> v.value()).isEqualTo("closed");
    }

    @Test
    void aGoToCommandMovesTheRobotToTheDoorWhichOpens() {
        await().atMost(DEADLINE).until(() -> edge.provider("robot3").map(p -> p.status() == ResourceStatus.OK)
                .orElse(false));
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot3";
        go.x = 9;
        go.y = 7;
        CommandOutcome outcome = edge.execute(go).join();
        assertThat(outcome.accepted).as(outcome.reason).isTrue();
        assertThat(outcome.missionId).isNotNull();
        sim.step(8);
        await().atMost(DEADLINE).until(() -> !sink.of(ObstacleDetected.class,
                e -> e.robotId.equals("robot3") && e.kind == ObstacleKind.DOOR).isEmpty());
        OpenDoorCommand open = new OpenDoorCommand();
        open.deviceId = "door1";
        assertThat(edge.execute(open).join().accepted).isTrue();
        sim.step(4);
        await().atMost(DEADLINE).until(() -> !sink.of(DoorStateChanged.class, e -> "open".equals(e.state)).isEmpty());
        sim.step(4);
        await().atMost(DEADLINE).until(() -> !sink.of(MissionFinished.class,
                e -> e.robotId.equals("robot3") && e.missionId == outcome.missionId).isEmpty());
        RobotPositionChanged last = sink.of(RobotPositionChanged.class, e -> e.robotId.equals("robot3")).stream()
                .reduce((a, b) -> b).orElseThrow();
        assertThat(last.x).isEqualTo(9);
        assertThat(last.y).isEqualTo(7);
    }
}
