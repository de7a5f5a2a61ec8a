package eu.brain.iot.behaviours.robot.impl;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;

/**
 * The recovery from a refused command: a refusal (or no outcome in time) is logged with the robot and the reason,
 * counted, and the command sent again up to {@code command.retries} times in a row; after that the robot's errand is
 * planned anew (what that means is the fleet's: {@code planAnew}). A refused cancel is not sent again: the go-to it
 * meant had ended.
 * <p>
 * Threads: the fleet's thread only ({@link RobotFleet#thread()}); {@link #replans} is read from any thread.
 */
final class Refusals {

    /** Wall time a command's outcome may take (the edge answers within its request timeout, 1 s by default). */
    static final long ANSWER_TIMEOUT_NANOS = TimeUnit.SECONDS.toNanos(4);
    /**
     * Wall time without an outcome after which a command to a robot that appeared on another node since counts as lost
     * (an outcome takes milliseconds; one published just before the hand-over may still be answered by the new owner).
     */
    static final long LOST_ON_HAND_OVER_NANOS = TimeUnit.SECONDS.toNanos(1);

    private static final System.Logger LOG = System.getLogger(Refusals.class.getName());

    private final RobotCommands commands;
    private final CommandLedger ledger;
    private final int retries;
    private final long answerTimeoutNanos;
    private final Consumer<String> planAnew;
    /** Refusals in a row per robot. */
    private final Map<String, Integer> inARow = new HashMap<>();
    private final AtomicLong replans = new AtomicLong();

    /**
     * @param retries  how many times a refused command is sent again before the errand is planned anew
     * @param answerTimeoutNanos wall time after which a command without outcome counts as refused
     * @param planAnew what the fleet does to a robot whose command was refused once too often
     */
    Refusals(RobotCommands commands, CommandLedger ledger, int retries, long answerTimeoutNanos,
            Consumer<String> planAnew) {
        this.commands = commands;
        this.ledger = ledger;
        this.retries = Math.max(0, retries);
        this.answerTimeoutNanos = answerTimeoutNanos;
        this.planAnew = planAnew;
    }

    /**
     * An outcome arrived on the bus: one answering a command of this behaviour's that is a refusal is handled; a
     * command sent again goes out in the refused one's place, before the robot's commands given after it.
     */
    void outcome(CommandOutcome o) {
        CommandLedger.Sent sent = commands.answered(o, refused -> refused(refused, o));
        if (sent != null && o.accepted) {
            inARow.remove(sent.command().deviceId);
        }
    }

    /** @return the command to send again in the refused one's place, or {@code null} for none */
    private EdgeCommand refused(CommandLedger.Sent sent, CommandOutcome o) {
        String robot = sent.command().deviceId;
        int n = inARow.merge(robot, 1, Integer::sum);
        String command = o.command != null ? o.command : sent.command().getClass().getSimpleName(); // none: lost
        LOG.log(System.Logger.Level.WARNING, "{0} refused {1} ({2}): {3} (status {4}); refusal {5} in a row", robot,
                command, sent.why(), o.reason, o.status, n);
        if (sent.command() instanceof CancelMissionCommand) {
            return null; // nothing to cancel: the robot's go-to had ended
        }
        if (n <= retries) {
            return RobotCommands.again(sent.command());
        }
        inARow.remove(robot);
        replans.incrementAndGet();
        planAnew.accept(robot);
        LOG.log(System.Logger.Level.WARNING, "{0}: errand planned anew after {1} refusals", robot, n);
        return null;
    }

    /**
     * A command without an outcome the answer timeout after it was published counts as refused (in a
     * fabric, the node that owned the robot may have died with it). An outcome that comes after all is not one of
     * the ledger's any more, and is ignored.
     */
    void expireUnanswered() {
        expire(ledger.unanswered(answerTimeoutNanos), "no outcome within "
                + TimeUnit.NANOSECONDS.toMillis(answerTimeoutNanos) + " ms of wall time (the node that owned the robot"
                + " may have stopped)");
    }

    /**
     * The robot appeared on a node that polls it now (a device taken over is announced as on discovery): a command to
     * it still without an outcome {@link #LOST_ON_HAND_OVER_NANOS} (at most the answer timeout) after it was published
     * went to the node that owned it before, and counts as refused now rather than at the answer timeout.
     */
    void handedOver(String robot) {
        long lostAfter = Math.min(LOST_ON_HAND_OVER_NANOS, answerTimeoutNanos);
        expire(ledger.unanswered(robot, lostAfter), "no outcome, and " + robot + " is polled by another node now: the"
                + " command went to the node that owned it before");
    }

    private void expire(List<String> commandIds, String reason) {
        for (String id : commandIds) {
            CommandOutcome lost = new CommandOutcome();
            lost.commandId = id;
            lost.accepted = false;
            lost.reason = reason;
            outcome(lost);
        }
    }

    /** @return the errands planned anew after refusals */
    long replans() {
        return replans.get();
    }
}
