package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.Map;
import java.util.function.Function;

import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;

/**
 * One robot's commands reach it in the order they were given: the next is published only when the edge has
 * answered the one before (the edge performs commands concurrently, so a go-to sent after a pick could otherwise
 * arrive first, and the robot would lift at the wrong cell). Per robot a queue; the outcome of its head releases
 * the next. Thread-safe: the queues are guarded by this object's monitor, and the bus is never called while it is
 * held (what to publish is chosen under the lock, published after).
 */
final class RobotCommands {

    private static final System.Logger LOG = System.getLogger(RobotCommands.class.getName());

    private record Waiting(EdgeCommand command, String why) {
    }

    private final CommandLedger ledger;
    /** Per robot: the command sent and not answered yet (head), then those waiting for it. */
    private final Map<String, ArrayDeque<Waiting>> queues = new HashMap<>();
    /** Per robot: the last pick it accepted. */
    private final Map<String, Accepted> lastPick = new HashMap<>();
    /** Per robot: the last go-to it accepted. */
    private final Map<String, Accepted> lastGoTo = new HashMap<>();
    /** Per robot: the last place it accepted. */
    private final Map<String, Accepted> lastPlace = new HashMap<>();

    /** A mission the robot accepted: the fleet's id of it, and when the answer came. */
    private record Accepted(long missionId, long atNanos) {
    }

    RobotCommands(CommandLedger ledger) {
        this.ledger = ledger;
    }

    /** Publishes the command now if the robot has none unanswered, else after those before it. */
    void send(EdgeCommand command, String why) {
        boolean now;
        synchronized (this) {
            ArrayDeque<Waiting> q = queues.computeIfAbsent(command.deviceId, k -> new ArrayDeque<>());
            q.add(new Waiting(command, why));
            now = q.size() == 1;
        }
        if (now) {
            publish(command, why);
        }
    }

    /**
     * An outcome arrived: when it answers one of these commands, the robot's next command goes out; but when it is a
     * refusal and {@code again} gives a command for it (called outside this object's monitor), that command goes out
     * in the refused one's place, ahead of those given after it (a place refused, then a go-to home given behind it:
     * the place is sent again before the robot leaves with its cart).
     *
     * @return what it answered, or {@code null} when it is not one of these commands
     */
    CommandLedger.Sent answered(CommandOutcome o, Function<CommandLedger.Sent, EdgeCommand> again) {
        CommandLedger.Sent sent = ledger.answered(o);
        if (sent != null) {
            if (o.accepted && o.missionId != null) {
                Accepted accepted = new Accepted(o.missionId, System.nanoTime());
                synchronized (this) {
                    if (sent.command() instanceof PickCartCommand) {
                        lastPick.put(sent.command().deviceId, accepted);
                    } else if (sent.command() instanceof GoToCommand) {
                        lastGoTo.put(sent.command().deviceId, accepted);
                    } else if (sent.command() instanceof PlaceCartCommand) {
                        lastPlace.put(sent.command().deviceId, accepted);
                    }
                }
            }
            EdgeCommand retry = o.accepted ? null : again.apply(sent);
            if (retry != null) {
                instead(retry, sent.why() + ", again");
            } else {
                next(sent.command().deviceId);
            }
        }
        return sent;
    }

    /** The robot's answered head replaced by {@code command}, published now; those behind it wait for its answer. */
    private void instead(EdgeCommand command, String why) {
        synchronized (this) {
            ArrayDeque<Waiting> q = queues.computeIfAbsent(command.deviceId, k -> new ArrayDeque<>());
            q.poll();
            q.addFirst(new Waiting(command, why));
        }
        publish(command, why);
    }

    /**
     * Whether a pick sent to the robot has not shown in the device model yet: it waits for its turn, waits for the
     * edge's answer, or was accepted as a mission newer than the one the device model shows.
     *
     * @param shownMission the robot's mission as the device model shows it ({@code null}: none yet)
     */
    synchronized boolean pickUnseen(String robot, Long shownMission) {
        return unseen(robot, PickCartCommand.class, lastPick, shownMission, Long.MAX_VALUE);
    }

    /**
     * Whether a place sent to the robot has not shown in the device model yet: it waits for its turn, waits for the
     * edge's answer, or was accepted as a mission newer than the one the device model shows.
     *
     * @param shownMission the robot's mission as the device model shows it ({@code null}: none yet)
     */
    synchronized boolean placeUnseen(String robot, Long shownMission) {
        return unseen(robot, PlaceCartCommand.class, lastPlace, shownMission, Long.MAX_VALUE);
    }

    /**
     * Whether a go-to sent to the robot has not shown in the device model yet: it waits for its turn, waits for the
     * edge's answer, or was accepted, less than {@code lostNanos} ago, as a mission newer than the one the device model
     * shows. Until it shows, the model's mission and cell are older than the go-to, and a go-to sent on them would
     * queue behind it. One accepted longer ago and never shown is taken as lost.
     *
     * @param shownMission the robot's mission as the device model shows it ({@code null}: none yet)
     * @param lostNanos    how long after its acceptance a go-to may not show yet
     */
    synchronized boolean goToUnseen(String robot, Long shownMission, long lostNanos) {
        return unseen(robot, GoToCommand.class, lastGoTo, shownMission, lostNanos);
    }

    /** Under this object's monitor: a command of the type queued or unanswered, or accepted and not shown yet. */
    private boolean unseen(String robot, Class<? extends EdgeCommand> type, Map<String, Accepted> last,
            Long shownMission, long lostNanos) {
        ArrayDeque<Waiting> q = queues.get(robot);
        if (q != null && q.stream().anyMatch(w -> type.isInstance(w.command()))) {
            return true;
        }
        Accepted a = last.get(robot);
        return a != null && (shownMission == null || shownMission < a.missionId())
                && System.nanoTime() - a.atNanos() < lostNanos;
    }

    /** @return whether a command sent to the robot has no answer from the edge yet */
    synchronized boolean unanswered(String robot) {
        ArrayDeque<Waiting> q = queues.get(robot);
        return q != null && !q.isEmpty();
    }

    private void next(String robot) {
        Waiting next;
        synchronized (this) {
            ArrayDeque<Waiting> q = queues.get(robot);
            if (q == null || q.isEmpty()) {
                return;
            }
            q.poll();
            next = q.peek();
        }
        if (next != null) {
            publish(next.command(), next.why());
        }
    }

    private void publish(EdgeCommand command, String why) {
        try {
            ledger.send(command, why);
        } catch (RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "{0}: {1} not sent ({2}): {3}", command.deviceId,
                    command.getClass().getSimpleName(), why, e.getMessage());
            next(command.deviceId); // not sent: no outcome will come for it
        }
    }

    /** @return a new command like {@code c} (without its commandId), to send it again */
    static EdgeCommand again(EdgeCommand c) {
        EdgeCommand again;
        if (c instanceof GoToCommand g) {
            GoToCommand go = new GoToCommand();
            go.x = g.x;
            go.y = g.y;
            again = go;
        } else if (c instanceof PickCartCommand) {
            again = new PickCartCommand();
        } else {
            again = new PlaceCartCommand();
        }
        again.deviceId = c.deviceId;
        return again;
    }
}
