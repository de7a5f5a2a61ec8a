package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.ObstacleKind;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.model.api.ResourceStatus;

/** The edge core against the real simulator over real HTTP (no framework). */
class EdgeAgainstSimTest {

    private static final Duration DEADLINE = Duration.ofSeconds(10);

    @RegisterExtension
    final EdgeOnSim fleet = new EdgeOnSim(url -> settings(url, List.of(), List.of()));

    private static FleetSettings settings(String url, List<String> robots, List<String> doors) {
        return FleetSettings.of(url, robots, doors, 100, 1000, 8, 1, 2, 400);
    }

    @Test
    void discoversTheFleetAndPublishesFirstPositions() {
        await().atMost(DEADLINE).until(() -> fleet.sink.of(RobotPositionChanged.class).size() >= 3);
        assertThat(fleet.edge.providers()).extracting(p -> p.id())
                .containsExactly("door1", "robot1", "robot2", "robot3");
        fleet.awaitAllOk(4);
        var r3 = fleet.sim.robot("robot3");
        assertThat(fleet.edge.resource("robot3", "position", "x")).get().extracting(v -> v.value()).isEqualTo(r3.x());
        assertThat(fleet.edge.resource("door1", "door", "state")).get().extracting(v -> v.value()).isEqualTo("closed");
    }

    @Test
    void aGoToCommandMovesTheRobotToTheDoorWhichOpens() {
        await().atMost(DEADLINE).until(() -> fleet.edge.provider("robot3").map(p -> p.status() == ResourceStatus.OK)
                .orElse(false));
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot3";
        go.x = 9;
        go.y = 7;
        CommandOutcome outcome = fleet.edge.execute(go).join();
        assertThat(outcome.accepted).as(outcome.reason).isTrue();
        assertThat(outcome.missionId).isNotNull();
        fleet.sim.step(8);
        await().atMost(DEADLINE).until(() -> !fleet.sink.of(ObstacleDetected.class,
                e -> e.robotId.equals("robot3") && e.kind == ObstacleKind.DOOR).isEmpty());
        OpenDoorCommand open = new OpenDoorCommand();
        open.deviceId = "door1";
        assertThat(fleet.edge.execute(open).join().accepted).isTrue();
        fleet.sim.step(4);
        await().atMost(DEADLINE)
                .until(() -> !fleet.sink.of(DoorStateChanged.class, e -> "open".equals(e.state)).isEmpty());
        fleet.sim.step(4);
        await().atMost(DEADLINE).until(() -> !fleet.sink.of(MissionFinished.class,
                e -> e.robotId.equals("robot3") && e.missionId == outcome.missionId).isEmpty());
        RobotPositionChanged last = fleet.sink.of(RobotPositionChanged.class, e -> e.robotId.equals("robot3")).stream()
                .reduce((a, b) -> b).orElseThrow();
        assertThat(last.x).isEqualTo(9);
        assertThat(last.y).isEqualTo(7);
    }
}
