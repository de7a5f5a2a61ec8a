package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.assertj.core.api.Assertions.assertThat;
import static eu.brain.iot.edge.integration.EdgeCommands.to;
import static org.awaitility.Awaitility.await;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CartLifted;
import eu.brain.iot.edge.api.CartPlaced;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.MissionFailed;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.ObstacleCleared;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.ObstacleKind;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;
import eu.brain.iot.edge.api.RobotEvent;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.robotsim.view.RobotView;

/**
 * A robot's whole errand through the bus in Felix (the in-framework twin of the unit test ScriptedRouteTest):
 * commands published as events, the simulator stepped one step at a time, and what a behaviour receives: every
 * cell of the route, the closed door in the way and then the way clear, the cart lifted and put down, and the end
 * of every mission, in order.
 */
class EdgeRouteIntegrationTest extends EdgeBusTestBase {

    /** Every 25 ms: each step of the route waits for one poll. */
    @Override
    Map<String, Object> edgeSettings() {
        return Map.of("poll.period.ms", 25L);
    }

    @Test
    void aBehaviourIsToldTheRouteTheDoorTheCartAndEveryMissionEnd() {
        // the door stays closed: robot3 meets it on its way to cart2
        List<Long> missions = new ArrayList<>();
        missions.add(accept(goTo(10, 7)));
        missions.add(accept(to(new PickCartCommand(), "robot3")));
        missions.add(accept(goTo(13, 2)));
        missions.add(accept(to(new PlaceCartCommand(), "robot3")));

        List<String> route = new ArrayList<>(recorder.follow(sim, "robot3", () -> sim.robot("robot3").detect() == 2,
                40));
        RobotView stopped = sim.robot("robot3");
        await("the door in robot3's way").atMost(DEADLINE).until(() -> !recorder.of(ObstacleDetected.class).isEmpty());
        assertThat(recorder.of(ObstacleCleared.class)).as("the door is still closed").isEmpty();

        accept(to(new OpenDoorCommand(), "door1"));
        List<String> rest = recorder.follow(sim, "robot3", () -> finished(missions.get(3)), 80);
        route.addAll(rest.subList(1, rest.size()));

        assertThat(recorder.of(RobotPositionChanged.class, "robot3")).extracting(BusRecorder::at)
                .containsExactlyElementsOf(route);
        assertThat(route).contains("10,7", "13,2");
        assertThat(recorder.of(ObstacleDetected.class, "robot3")).singleElement().satisfies(e -> {
            assertThat(e.kind).isEqualTo(ObstacleKind.DOOR);
            assertThat(e.detect).isEqualTo(2);
            assertThat(e.x + "," + e.y).isEqualTo(BusRecorder.at(stopped));
        });
        assertThat(recorder.of(ObstacleCleared.class, "robot3")).singleElement()
                .satisfies(e -> assertThat(e.kind).isEqualTo(ObstacleKind.DOOR));
        assertThat(recorder.of(CartLifted.class, "robot3")).singleElement().satisfies(e -> {
            assertThat(e.cartId).isEqualTo("cart2");
            assertThat(e.x + "," + e.y).isEqualTo("10,7");
        });
        await("the cart put down").atMost(DEADLINE).until(() -> !recorder.of(CartPlaced.class).isEmpty());
        assertThat(recorder.of(CartPlaced.class, "robot3")).singleElement().satisfies(e -> {
            assertThat(e.cartId).isEqualTo("cart2");
            assertThat(e.x + "," + e.y).isEqualTo("13,2");
        });
        await("every mission's end").atMost(DEADLINE).until(() -> recorder.of(MissionFinished.class).size() == 4);
        assertThat(recorder.of(MissionFinished.class, "robot3")).extracting(e -> e.missionId)
                .containsExactlyElementsOf(missions);
        assertThat(recorder.of(MissionFinished.class)).extracting(e -> e.missionType)
                .containsExactly("goto", "pick", "goto", "place");
        assertThat(recorder.of(MissionFailed.class)).isEmpty();
        // one story, in the order it happened
        assertThat(story("robot3")).containsSubsequence("at " + BusRecorder.at(stopped), "ObstacleDetected",
                "ObstacleCleared", "at 10,7", "CartLifted", "at 13,2", "CartPlaced");
        assertThat(story("robot3")).containsSubsequence("MissionFinished goto", "MissionFinished pick",
                "MissionFinished goto", "MissionFinished place");
    }

    @Test
    void aCancelledMissionIsToldAsFailed() {
        long mission = accept(goTo(17, 4));
        recorder.follow(sim, "robot3", () -> !BusRecorder.at(sim.robot("robot3")).equals("6,1"), 5); // on its way
        CancelMissionCommand cancel = to(new CancelMissionCommand(), "robot3");
        cancel.missionId = mission;
        accept(cancel);
        await("the mission's end").atMost(DEADLINE).until(() -> !recorder.of(MissionFailed.class).isEmpty());
        assertThat(recorder.of(MissionFailed.class)).singleElement().satisfies(e -> {
            assertThat(e.robotId).isEqualTo("robot3");
            assertThat(e.missionId).isEqualTo(mission);
            assertThat(e.missionType).isEqualTo("goto");
            assertThat(e.reason).isEqualTo("cancelled");
        });
        assertThat(recorder.of(MissionFinished.class)).isEmpty();
    }

    /** The robot's events as a behaviour saw them: "at x,y" for a move, else the event's name (and mission type). */
    private List<String> story(String robotId) {
        return recorder.of(RobotEvent.class, robotId).stream().map(e -> e instanceof RobotPositionChanged p
                ? "at " + BusRecorder.at(p)
                : e instanceof MissionFinished m ? "MissionFinished " + m.missionType : e.getClass().getSimpleName())
                .toList();
    }

    private boolean finished(long mission) {
        return EdgeCommands.finished(sim.robot("robot3"), mission);
    }

    private static GoToCommand goTo(int x, int y) {
        return EdgeCommands.goTo("robot3", x, y);
    }

    /** The command, published on the bus and accepted: the id of the mission it queued (-1: none). */
    private long accept(EdgeCommand command) {
        Long mission = recorder.send(bus, command).missionId;
        return mission == null ? -1 : mission;
    }
}
