package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static eu.brain.iot.edge.integration.EdgeCommands.to;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

import eu.brain.iot.edge.api.CartLifted;
import eu.brain.iot.edge.api.CartPlaced;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.MissionFailed;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.edge.integration.EdgeCommands;
import eu.brain.iot.robotsim.view.RobotView;

/**
 * A robot's whole errand, step by step (the paper's REQ-1): through the door to a cart, lift it, carry it to
 * storage, put it down. After every step the edge must show the simulator's position; the events must tell
 * exactly the route, the cart and the end of every mission.
 */
class ScriptedRouteTest {

    private static final Duration DEADLINE = Duration.ofSeconds(10);

    @RegisterExtension
    final EdgeOnSim fleet = new EdgeOnSim(url -> FleetSettings.of(url, List.of("robot3"), List.of("door1"), 50, 1000,
            8, 1, 3, 400));

    @BeforeEach
    void allPolled() {
        fleet.awaitAllOk(2);
    }

    @Test
    void eventsTellTheRouteTheCartAndEveryMissionEnd() {
        accept(to(new OpenDoorCommand(), "door1"));
        List<Long> missions = new ArrayList<>();
        missions.add(accept(goTo(10, 7))); // cart2 stands there
        missions.add(accept(to(new PickCartCommand(), "robot3")));
        missions.add(accept(goTo(13, 2)));
        missions.add(accept(to(new PlaceCartCommand(), "robot3")));

        List<String> route = new ArrayList<>();
        RobotView start = fleet.sim.robot("robot3");
        route.add(start.x() + "," + start.y());
        for (int step = 0; step < 80 && !finished(missions.get(3)); step++) {
            fleet.sim.step(1);
            RobotView now = fleet.sim.robot("robot3");
            await().atMost(DEADLINE).until(() -> Objects.equals(fleet.edge.resource("robot3", "position", "x")
                    .orElseThrow().value(), now.x()) && Objects.equals(fleet.edge.resource("robot3", "position", "y")
                    .orElseThrow().value(), now.y()) && Objects.equals(fleet.edge.resource("robot3", "cart", "cart")
                    .orElseThrow().value(), now.cart()));
            if (!route.get(route.size() - 1).equals(now.x() + "," + now.y())) {
                route.add(now.x() + "," + now.y());
            }
        }
        assertThat(finished(missions.get(3))).as("the errand ends within 80 steps: " + fleet.sim.robot("robot3")
                + " " + fleet.sim.door("door1")).isTrue();

        List<String> announced = fleet.sink.of(RobotPositionChanged.class).stream().map(e -> e.x + "," + e.y).toList();
        assertThat(announced).containsExactlyElementsOf(route);
        assertThat(route).contains("10,7", "13,2");
        assertThat(fleet.sink.of(CartLifted.class)).singleElement().satisfies(e -> {
            assertThat(e.cartId).isEqualTo("cart2");
            assertThat(e.x + "," + e.y).isEqualTo("10,7");
        });
        assertThat(fleet.sink.of(CartPlaced.class)).singleElement().satisfies(e -> {
            assertThat(e.cartId).isEqualTo("cart2");
            assertThat(e.x + "," + e.y).isEqualTo("13,2");
        });
        await().atMost(DEADLINE).until(() -> fleet.sink.of(MissionFinished.class).size() == 4);
        assertThat(fleet.sink.of(MissionFinished.class)).extracting(e -> e.missionId)
                .containsExactlyElementsOf(missions);
        assertThat(fleet.sink.of(MissionFinished.class)).extracting(e -> e.missionType)
                .containsExactly("goto", "pick", "goto", "place");
        assertThat(fleet.sink.of(MissionFailed.class)).isEmpty();
    }

    @Test
    void aMissionThatEndsBetweenTwoPollsIsStillAnnouncedFromTheRobotsHistory() {
        long first = accept(goTo(6, 2));
        long second = accept(goTo(6, 3));
        long polled = fleet.edge.pollStats().answered();
        await().atMost(DEADLINE).until(() -> fleet.edge.pollStats().answered() > polled + 2);
        // stop the edge from seeing the first mission's end: both missions end within one batch of steps
        fleet.sim.step(10);
        await().atMost(DEADLINE).until(() -> fleet.sink.of(MissionFinished.class).size() == 2);
        assertThat(fleet.sink.of(MissionFinished.class)).extracting(e -> e.missionId).containsExactly(first, second);
    }

    private boolean finished(long mission) {
        return EdgeCommands.finished(fleet.sim.robot("robot3"), mission);
    }

    private static GoToCommand goTo(int x, int y) {
        return EdgeCommands.goTo("robot3", x, y);
    }

    private long accept(EdgeCommand command) {
        CommandOutcome outcome = fleet.edge.execute(command).join();
        assertThat(outcome.accepted).as(outcome.reason).isTrue();
        // published too, by the fleet thread, in line with the edge's other events
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(fleet.sink.of(CommandOutcome.class)).contains(outcome));
        return outcome.missionId == null ? -1 : outcome.missionId;
    }
}
