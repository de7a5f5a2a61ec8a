package eu.brain.iot.behaviours.warehouse;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.eventing.api.EventBus;

/**
 * The commands one behaviour sent to the edge, each published on the bus with a commandId of its own (prefix and
 * a counter), kept until its {@link CommandOutcome} comes back; counts what was sent, accepted and refused.
 * Thread-safe (concurrent map and atomic counters): externs send on the bus's delivery thread, outcomes arrive on
 * another behaviour's.
 */
public final class CommandLedger {

    /** A command waiting for its outcome, and why it was sent (for the log when it is refused). */
    public record Sent(EdgeCommand command, String why) {
    }

    private final EventBus bus;
    private final String prefix;
    private final AtomicLong next = new AtomicLong();
    private final Map<String, Sent> pending = new ConcurrentHashMap<>();
    /** When each pending command was published ({@link System#nanoTime()}). */
    private final Map<String, Long> sentAt = new ConcurrentHashMap<>();
    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong accepted = new AtomicLong();
    private final AtomicLong refused = new AtomicLong();

    /** @param prefix starts every commandId of this behaviour, e.g. {@code robot-} */
    public CommandLedger(EventBus bus, String prefix) {
        this.bus = bus;
        this.prefix = prefix;
    }

    /**
     * Publishes a command for the edge.
     *
     * @return the commandId given to it
     * @throws eu.brain.iot.eventing.api.EventBusOverflowException when the bus cannot take it (nothing was sent)
     */
    public String send(EdgeCommand command, String why) {
        command.commandId = prefix + next.incrementAndGet();
        pending.put(command.commandId, new Sent(command, why));
        sentAt.put(command.commandId, System.nanoTime());
        try {
            bus.deliver(command);
        } catch (RuntimeException e) {
            pending.remove(command.commandId);
            sentAt.remove(command.commandId);
            throw e;
        }
        sent.incrementAndGet();
        return command.commandId;
    }

    /**
     * An outcome arrived: when it answers one of this ledger's commands, it is counted and the command is no longer
     * pending.
     *
     * @return the command it answers, or {@code null} when it is not one of this ledger's
     */
    public Sent answered(CommandOutcome outcome) {
        Sent s = outcome.commandId == null ? null : pending.remove(outcome.commandId);
        if (s != null) {
            sentAt.remove(outcome.commandId);
            (outcome.accepted ? accepted : refused).incrementAndGet();
        }
        return s;
    }

    /**
     * @param olderThanNanos how long ago, at least, the command was published
     * @return the commandIds of the commands still without an outcome that long after they were published (in a
     *         fabric, the node that owned the device may have died with the command)
     */
    public List<String> unanswered(long olderThanNanos) {
        return unanswered(null, olderThanNanos);
    }

    /**
     * @param deviceId       the device the commands were sent to; {@code null}: any device
     * @param olderThanNanos how long ago, at least, the command was published
     * @return the commandIds of the commands to the device still without an outcome that long after they were
     *         published
     */
    public List<String> unanswered(String deviceId, long olderThanNanos) {
        long now = System.nanoTime();
        List<String> late = new ArrayList<>();
        sentAt.forEach((id, at) -> {
            Sent s = pending.get(id);
            if (now - at > olderThanNanos && s != null && (deviceId == null || deviceId.equals(s.command().deviceId))) {
                late.add(id);
            }
        });
        return late;
    }

    public long sent() {
        return sent.get();
    }

    public long accepted() {
        return accepted.get();
    }

    public long refused() {
        return refused.get();
    }

    /** @return commands sent whose outcome has not come yet */
    public int pending() {
        return pending.size();
    }
}
