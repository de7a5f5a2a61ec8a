package eu.brain.iot.edge.impl;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

import eu.brain.iot.edge.api.DeviceReport;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The edge's one way out to the bus, for polling, missions and commands alike: it never waits and never drops
 * an event silently.
 * <p>
 * An event goes straight to the {@link EventSink} (the bus's {@code tryDeliver}) while nothing is waiting here.
 * When the bus refuses one (a behaviour's queue is full), that event and every later one wait here, in publish
 * order, and {@link #flush()} (every tick of the fleet thread) sends them as the bus takes them again. So a slow
 * behaviour delays the edge's events, but never its polling.
 * <p>
 * Under that pressure a robot's position is <em>coalesced</em>: a new {@link RobotPositionChanged} replaces the
 * robot's one still waiting (it moves to the end of the line, keeping the older one's {@code previousX/Y}, which
 * is where behaviours last heard the robot was), so waiting positions are bounded by the fleet's size. So is a
 * {@link DeviceReport}: a new one replaces a waiting one of the same devices (it says all the older one said, newer),
 * at the end of the line. Every other event (obstacles, carts, doors, mission ends, reachability, command outcomes)
 * waits whole: those are what the orchestration rests on. Counters say how many events were refused, waited and were
 * coalesced; the first refusal after a quiet spell, and every minute while it lasts, is logged.
 * <p>
 * Ownership: the fleet thread alone calls every method except the counters' getters (volatile/adders read by
 * the statistics); events from other threads (command outcomes) are handed to the fleet thread first.
 */
final class Outbox {

    /**
     * Where an event waits: a slot that a newer event of the same kind about the same devices takes over (a robot's
     * position, a report of the same devices), or a slot of its own ({@code coalesceKey} null, {@code seq} unique).
     */
    private record Slot(String coalesceKey, long seq) {
    }

    private static final long WARN_EVERY_MILLIS = 60_000;

    private final EventSink sink;
    private final EdgeLog log;
    private final LinkedHashMap<Slot, BrainIoTEvent> waiting = new LinkedHashMap<>();
    private long seq;
    private long lastWarnMillis;
    private volatile int depth;
    private volatile long refusals;
    private volatile long coalesced;
    private volatile long reportsReplaced;
    private volatile long failed;

    Outbox(EventSink sink, EdgeLog log) {
        this.sink = sink;
        this.log = log;
    }

    /** Send an event, or keep it in line behind those already waiting. */
    void publish(BrainIoTEvent event) {
        if (waiting.isEmpty() && offer(event)) {
            return;
        }
        if (event instanceof RobotPositionChanged position) {
            Slot slot = new Slot("position of " + position.robotId, 0);
            BrainIoTEvent older = waiting.remove(slot);
            if (older instanceof RobotPositionChanged replaced) {
                position.previousX = replaced.previousX;
                position.previousY = replaced.previousY;
                coalesced++;
            }
            waiting.put(slot, position);
        } else if (event instanceof DeviceReport report) {
            Slot slot = new Slot("report of " + reportedIds(report), 0);
            if (waiting.remove(slot) != null) {
                reportsReplaced++;
            }
            waiting.put(slot, report);
        } else {
            waiting.put(new Slot(null, ++seq), event);
        }
        depth = waiting.size();
    }

    /** Send what waits, oldest first, until the bus refuses one. */
    void flush() {
        if (waiting.isEmpty()) {
            return;
        }
        for (Iterator<Map.Entry<Slot, BrainIoTEvent>> it = waiting.entrySet().iterator(); it.hasNext();) {
            if (!offer(it.next().getValue())) {
                break;
            }
            it.remove();
        }
        depth = waiting.size();
        if (waiting.isEmpty()) {
            log.info("the event bus takes the edge's events again; every waiting event was sent (" + coalesced
                    + " robot positions coalesced so far)");
            lastWarnMillis = 0;
        }
    }

    /** @return whether the sink took the event, or dropped it for good after an error that was logged */
    private boolean offer(BrainIoTEvent event) {
        boolean taken;
        try {
            taken = sink.offer(event);
        } catch (RuntimeException e) {
            // Not a full queue but a refusal that retrying cannot cure (the bus is going away, a bad event).
            failed++;
            log.warn("could not publish " + event.getClass().getSimpleName() + ": " + e.getMessage());
            return true;
        }
        if (!taken) {
            refusals++;
            long now = System.currentTimeMillis();
            if (now - lastWarnMillis >= WARN_EVERY_MILLIS) {
                lastWarnMillis = now;
                log.warn("the event bus refused an edge event (a smart behaviour's queue is full: see bus:behaviours); "
                        + "the edge keeps its events in order (" + waiting.size() + " waiting, robot positions "
                        + "coalesced) and sends them as the bus takes them again; polling goes on");
            }
        }
        return taken;
    }

    /** The ids a report names, in its order (the edge writes them sorted). */
    private static String reportedIds(DeviceReport report) {
        StringBuilder ids = new StringBuilder();
        if (report.devices != null) {
            for (Map<String, Object> device : report.devices) {
                ids.append(device.get("id")).append(',');
            }
        }
        return ids.toString();
    }

    /** Events waiting now. */
    int depth() {
        return depth;
    }

    boolean isEmpty() {
        return waiting.isEmpty();
    }

    /** Times the bus refused an event (an event retried later counts again). */
    long refusals() {
        return refusals;
    }

    /** Robot positions replaced by a newer one while they waited. */
    long coalesced() {
        return coalesced;
    }

    /** Device reports replaced by a newer one of the same devices while they waited. */
    long reportsReplaced() {
        return reportsReplaced;
    }

    /** Events the bus rejected with an error (logged each time). */
    long failed() {
        return failed;
    }
}
