package eu.brain.iot.behaviours.robot.impl;

import static eu.brain.iot.behaviours.robot.impl.RobotCommandsTest.outcome;
import static eu.brain.iot.behaviours.robot.impl.RobotCommandsTest.to;
import static org.assertj.core.api.Assertions.assertThat;

import java.text.MessageFormat;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;

/** A refused command is sent again a few times in a row, then the robot's errand is planned anew. */
class RefusalsTest {

    final RobotCommandsTest.Bus bus = new RobotCommandsTest.Bus();
    final CommandLedger ledger = new CommandLedger(bus, "r-");
    final RobotCommands commands = new RobotCommands(ledger);
    final List<String> plannedAnew = new CopyOnWriteArrayList<>();
    final Refusals refusals = new Refusals(commands, ledger, 2, Refusals.ANSWER_TIMEOUT_NANOS,
            plannedAnew::add);

    private EdgeCommand last() {
        return bus.sent.get(bus.sent.size() - 1);
    }

    @Test
    void aRefusedGoToIsSentAgainUpToTheRetriesThenTheErrandIsPlannedAnew() {
        GoToCommand go = to(new GoToCommand(), "robot1");
        go.x = 4;
        go.y = 7;
        commands.send(go, "to the cart");

        refusals.outcome(outcome(last(), false, null));
        refusals.outcome(outcome(last(), false, null));
        assertThat(bus.sent).hasSize(3).allSatisfy(c -> assertThat(((GoToCommand) c).x).isEqualTo(4));
        assertThat(plannedAnew).isEmpty();

        refusals.outcome(outcome(last(), false, null));
        assertThat(bus.sent).as("no fourth try").hasSize(3);
        assertThat(plannedAnew).containsExactly("robot1");
        assertThat(refusals.replans()).isEqualTo(1);
    }

    @Test
    void anAcceptedCommandEndsTheRunOfRefusals() {
        commands.send(to(new GoToCommand(), "robot1"), "to the cart");
        refusals.outcome(outcome(last(), false, null));
        refusals.outcome(outcome(last(), false, null));
        refusals.outcome(outcome(last(), true, 3L));

        commands.send(to(new GoToCommand(), "robot1"), "to the door");
        refusals.outcome(outcome(last(), false, null));
        refusals.outcome(outcome(last(), false, null));
        assertThat(plannedAnew).as("two in a row since the last accepted").isEmpty();
    }

    @Test
    void aRefusedCancelIsNotSentAgain() {
        commands.send(to(new CancelMissionCommand(), "robot2"), "stepping aside");
        refusals.outcome(outcome(last(), false, null));
        assertThat(bus.sent).hasSize(1);
        assertThat(plannedAnew).isEmpty();
    }

    @Test
    void aCommandLeftWithoutOutcomeCountsAsRefused() {
        commands.send(to(new GoToCommand(), "robot3"), "to a node that died with it");
        refusals.expireUnanswered();
        assertThat(bus.sent).as("within the answer timeout: still waiting").hasSize(1);

        Refusals impatient = new Refusals(commands, ledger, 0, 0, plannedAnew::add);
        impatient.expireUnanswered();
        assertThat(plannedAnew).containsExactly("robot3");
        assertThat(ledger.unanswered(0)).isEmpty();
    }

    @Test
    void aCommandLeftWithoutOutcomeIsLoggedByItsKind() {
        List<String> warnings = new CopyOnWriteArrayList<>();
        Handler handler = new Handler() {
            @Override
            public void publish(LogRecord r) {
                warnings.add(MessageFormat.format(r.getMessage(), r.getParameters()));
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger jul = Logger.getLogger(Refusals.class.getName());
        jul.addHandler(handler);
        try {
            commands.send(to(new GoToCommand(), "robot3"), "a leg");
            new Refusals(commands, ledger, 2, 0, plannedAnew::add).expireUnanswered();
        } finally {
            jul.removeHandler(handler);
        }
        assertThat(warnings)
                .anySatisfy(w -> assertThat(w).startsWith("robot3 refused GoToCommand (a leg): no outcome"));
    }

    @Test
    void aRobotThatAppearedOnAnotherNodeHasItsCommandsLeftWithoutOutcomeSentAgainAtOnce() {
        commands.send(to(new GoToCommand(), "robot3"), "a leg, to the node that let robot3 go");
        commands.send(to(new GoToCommand(), "robot1"), "a leg");
        refusals.handedOver("robot3");
        assertThat(bus.sent).as("published just now: its outcome may still come").hasSize(2);

        Refusals impatient = new Refusals(commands, ledger, 2, 0, plannedAnew::add);
        impatient.handedOver("robot3");
        assertThat(bus.sent).as("robot3's leg again, to its new owner").hasSize(3);
        assertThat(last().deviceId).isEqualTo("robot3");
        assertThat(ledger.unanswered("robot1", 0)).as("robot1's leg is left alone").hasSize(1);
        assertThat(plannedAnew).isEmpty();
    }

    @Test
    void aCommandSentAgainGoesOutBeforeTheOnesGivenAfterIt() {
        commands.send(to(new PlaceCartCommand(), "robot3"), "placing its cart in storage");
        GoToCommand home = to(new GoToCommand(), "robot3");
        home.x = 6;
        home.y = 1;
        commands.send(home, "going home"); // waits for the place's answer

        Refusals impatient = new Refusals(commands, ledger, 2, 0, plannedAnew::add);
        impatient.expireUnanswered(); // its node died with it: no outcome
        assertThat(bus.sent).as("the place again, not the robot leaving with its cart").hasSize(2);
        assertThat(last()).isInstanceOf(PlaceCartCommand.class);

        refusals.outcome(outcome(last(), true, 8L));
        assertThat(bus.sent).hasSize(3);
        assertThat(last()).isInstanceOf(GoToCommand.class);
        assertThat(((GoToCommand) last()).y).isEqualTo(1);
        assertThat(plannedAnew).isEmpty();
    }

    @Test
    void anOutcomeOfAnotherBehavioursCommandIsIgnored() {
        GoToCommand foreign = to(new GoToCommand(), "robot1");
        foreign.commandId = "someone-else-1";
        refusals.outcome(outcome(foreign, false, null));
        assertThat(bus.sent).isEmpty();
        assertThat(plannedAnew).isEmpty();
    }
}
