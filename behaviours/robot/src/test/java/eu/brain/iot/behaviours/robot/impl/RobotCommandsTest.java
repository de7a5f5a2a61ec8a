package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;

/** One robot's commands in order, and whether a pick sent to it has shown in the device model yet. */
class RobotCommandsTest {

    /** Keeps the commands published. */
    static final class Bus implements EventBus {
        final List<EdgeCommand> sent = new CopyOnWriteArrayList<>();

        @Override
        public void deliver(BrainIoTEvent event) {
            sent.add((EdgeCommand) event);
        }

        @Override
        public void deliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException();
        }

        @Override
        public boolean tryDeliver(BrainIoTEvent event) {
            deliver(event);
            return true;
        }

        @Override
        public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException();
        }
    }

    final Bus bus = new Bus();
    final RobotCommands commands = new RobotCommands(new CommandLedger(bus, "t-"));

    static <C extends EdgeCommand> C to(C command, String robot) {
        command.deviceId = robot;
        return command;
    }

    static CommandOutcome outcome(EdgeCommand c, boolean accepted, Long mission) {
        CommandOutcome o = new CommandOutcome();
        o.commandId = c.commandId;
        o.deviceId = c.deviceId;
        o.accepted = accepted;
        o.missionId = mission;
        return o;
    }

    @Test
    void theNextCommandOfARobotGoesOutOnlyOnceTheOneBeforeIsAnswered() {
        PickCartCommand pick = to(new PickCartCommand(), "robot1");
        GoToCommand go = to(new GoToCommand(), "robot1");
        GoToCommand other = to(new GoToCommand(), "robot2");
        commands.send(pick, "lifting");
        commands.send(go, "to storage");
        commands.send(other, "elsewhere");
        assertThat(bus.sent).containsExactly(pick, other);

        commands.answered(outcome(pick, true, 7L), sent -> null);
        assertThat(bus.sent).containsExactly(pick, other, go);
    }

    @Test
    void aPickIsUnseenWhileItWaitsIsUnansweredOrIsNewerThanTheMissionTheDeviceModelShows() {
        GoToCommand go = to(new GoToCommand(), "robot1");
        PickCartCommand pick = to(new PickCartCommand(), "robot1");
        assertThat(commands.pickUnseen("robot1", null)).as("nothing sent").isFalse();

        commands.send(go, "to the cart");
        commands.send(pick, "lifting");
        assertThat(commands.pickUnseen("robot1", 3L)).as("waiting behind the go-to").isTrue();
        commands.answered(outcome(go, true, 4L), sent -> null);
        assertThat(commands.pickUnseen("robot1", 4L)).as("sent, not answered").isTrue();
        commands.answered(outcome(pick, true, 5L), sent -> null);
        assertThat(commands.pickUnseen("robot1", 4L)).as("accepted; the device model shows the go-to still")
                .isTrue();
        assertThat(commands.pickUnseen("robot1", 5L)).as("the device model shows the pick").isFalse();
        assertThat(commands.pickUnseen("robot2", null)).as("another robot").isFalse();
    }

    @Test
    void aRobotTakenOverWhilePlacingHasNoPickUnseenWhateverItIsToldAfter() {
        // the behaviour started again: a place it did not send finished, then a go-to it sent ended
        GoToCommand go = to(new GoToCommand(), "robot2");
        commands.send(go, "carrying cart1 to storage");
        commands.answered(outcome(go, true, 12L), sent -> null);
        assertThat(commands.pickUnseen("robot2", 12L)).isFalse();
    }

    @Test
    void aPlaceIsUnseenWhileItWaitsIsUnansweredOrIsNewerThanTheMissionTheDeviceModelShowsButNotOnceRefused() {
        PlaceCartCommand place = to(new PlaceCartCommand(), "robot1");
        GoToCommand home = to(new GoToCommand(), "robot1");
        assertThat(commands.placeUnseen("robot1", 7L)).as("nothing sent").isFalse();
        commands.send(place, "placing");
        commands.send(home, "going home");
        assertThat(commands.placeUnseen("robot1", 7L)).as("sent, not answered").isTrue();
        commands.answered(outcome(place, true, 8L), sent -> null);
        assertThat(commands.placeUnseen("robot1", 7L)).as("accepted; the device model shows the go-to before")
                .isTrue();
        assertThat(commands.placeUnseen("robot1", 8L)).as("the device model shows the place").isFalse();

        PlaceCartCommand refused = to(new PlaceCartCommand(), "robot2");
        commands.send(refused, "placing");
        commands.answered(outcome(refused, false, null), sent -> null);
        assertThat(commands.placeUnseen("robot2", 3L)).as("refused, not sent again: lost").isFalse();
    }

    @Test
    void aRefusedPickIsNotUnseenButOneSentAgainIs() {
        PickCartCommand pick = to(new PickCartCommand(), "robot1");
        commands.send(pick, "lifting");
        commands.answered(outcome(pick, false, null), sent -> null);
        assertThat(commands.pickUnseen("robot1", 2L)).isFalse();
        commands.send(to(new PlaceCartCommand(), "robot1"), "placing");
        assertThat(commands.pickUnseen("robot1", 2L)).isFalse();
        commands.send(to(new PickCartCommand(), "robot1"), "lifting, again");
        assertThat(commands.pickUnseen("robot1", 2L)).isTrue();
    }

    @Test
    void aCommandWithoutOutcomeIsListedAsUnansweredUntilItsOutcomeComesThenTheNextGoesOut() {
        CommandLedger ledger = new CommandLedger(bus, "u-");
        RobotCommands queue = new RobotCommands(ledger);
        GoToCommand lost = to(new GoToCommand(), "robot1");
        GoToCommand next = to(new GoToCommand(), "robot1");
        queue.send(lost, "to a node that died with it");
        queue.send(next, "after it");

        assertThat(ledger.unanswered(0)).containsExactly(lost.commandId);
        assertThat(ledger.unanswered(java.util.concurrent.TimeUnit.HOURS.toNanos(1))).isEmpty();
        CommandOutcome timedOut = new CommandOutcome();
        timedOut.commandId = lost.commandId; // what Refusals.expireUnanswered makes of it
        assertThat(queue.answered(timedOut, sent -> null)).isNotNull();
        assertThat(bus.sent).containsExactly(lost, next);
        assertThat(ledger.unanswered(0)).containsExactly(next.commandId);
        assertThat(queue.answered(outcome(lost, true, null), sent -> null)).as("the real outcome, late").isNull();
    }
}
