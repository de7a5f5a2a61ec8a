package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.awaitility.Awaitility.await;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.model.api.UnknownResourceException;

/** A command that cannot be done is rejected with the reason, published like any outcome; nothing else changes. */
class CommandRejectionTest {

    @RegisterExtension
    final EdgeOnSim fleet = new EdgeOnSim(url -> FleetSettings.of(url, List.of(), List.of(), 100, 1000, 8, 1, 2, 400));

    private final java.util.concurrent.atomic.AtomicInteger commands = new java.util.concurrent.atomic.AtomicInteger();

    @BeforeEach
    void allPolled() {
        fleet.awaitAllOk(4);
    }

    private CommandOutcome run(EdgeCommand command, String device) {
        command.deviceId = device;
        command.commandId = "c-" + commands.incrementAndGet();
        CommandOutcome outcome = fleet.edge.execute(command).join();
        assertThat(outcome.commandId).isEqualTo(command.commandId);
        // published too, by the fleet thread, in line with the edge's other events
        await().atMost(EdgeOnSim.DEADLINE)
                .untilAsserted(() -> assertThat(fleet.sink.of(CommandOutcome.class)).contains(outcome));
        return outcome;
    }

    @Test
    void theDevicesReasonIsPassedOn() {
        GoToCommand wall = new GoToCommand();
        wall.x = 0;
        wall.y = 0;
        CommandOutcome outcome = run(wall, "robot1");
        assertThat(outcome.accepted).isFalse();
        assertThat(outcome.status).isEqualTo(422);
        assertThat(outcome.reason).isEqualTo("goal (0,0) is a wall");
        assertThat(fleet.sim.robot("robot1").mission()).isNull();
    }

    @Test
    void theEdgeRefusesWhatItCannotSend() {
        CommandOutcome unknown = run(new OpenDoorCommand(), "door9");
        assertThat(unknown.accepted).isFalse();
        assertThat(unknown.status).isZero();
        assertThat(unknown.reason).isEqualTo("unknown device 'door9' (robots: [robot1, robot2, robot3], doors: [door1])");

        assertThat(run(new OpenDoorCommand(), "robot1").reason).isEqualTo("OpenDoorCommand is for a door; robot1 is a robot");
        assertThat(run(new GoToCommand(), null).reason).isEqualTo("GoToCommand has no deviceId");
        CancelMissionCommand cancel = new CancelMissionCommand();
        cancel.missionType = "dance";
        assertThat(run(cancel, "robot2").reason).isEqualTo("missionType must be goto, pick or place, found 'dance'");
    }

    @Test
    void anUnreachableDeviceRejectsWithTheConnectionProblem() {
        SimAdmin.fault(fleet.sim, "robot3", "{\"offline\":true}");
        CommandOutcome outcome = run(new GoToCommand(), "robot3");
        assertThat(outcome.accepted).isFalse();
        assertThat(outcome.status).isEqualTo(503);
        assertThat(outcome.reason).isEqualTo("robot robot3 is offline");
    }

    @Test
    void actionsCheckTheirParameters() {
        assertThatThrownBy(() -> fleet.edge.act("robot1", "control", "goTo", Map.of("x", "9", "y", 7)))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("parameter 'x' must be a whole number, found 9 (a string)");
        assertThatThrownBy(() -> fleet.edge.act("robot1", "control", "goTo", Map.of("x", 9)))
                .hasMessage("parameter 'y' is missing");
        assertThatThrownBy(() -> fleet.edge.act("robot1", "control", "goTo", Map.of("x", 9, "y", 7, "z", 1)))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("unknown parameter 'z': goTo takes [x, y]");
        assertThatThrownBy(() -> fleet.edge.act("robot1", "control", "pick", Map.of("foo", 1)))
                .hasMessage("unknown parameter 'foo': pick takes no parameters");
        assertThatThrownBy(() -> fleet.edge.act("robot1", "control", "fly", Map.of()))
                .isInstanceOf(UnknownResourceException.class).hasMessageContaining("robot1 has no action 'fly'");
        assertThatThrownBy(() -> fleet.edge.act("robot7", "control", "pick", Map.of()))
                .isInstanceOf(UnknownResourceException.class).hasMessageContaining("no provider 'robot7'");
        CommandOutcome open = fleet.edge.act("door1", "control", "open", Map.of()).toCompletableFuture().join();
        assertThat(open.accepted).isTrue();
        assertThat(fleet.sim.door("door1").state()).isEqualTo("opening");
    }
}
