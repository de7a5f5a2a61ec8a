package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import eu.brain.iot.edge.api.CartLifted;
import eu.brain.iot.edge.api.CartPlaced;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.MissionFailed;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.ObstacleCleared;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.ObstacleKind;
import eu.brain.iot.edge.api.RobotEvent;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * Turns two successive answers of a device into resource values (in the {@link DeviceStore}) and the events of
 * what changed. Stateless; called on the fleet thread.
 */
final class ChangeDetector {

    private ChangeDetector() {
    }

    /** @param before the previous answer, {@code null} the first time (then only the position is announced) */
    static List<BrainIoTEvent> robot(DeviceStore store, RobotAnswer before, RobotAnswer now, Instant at) {
        String id = now.id();
        store.set(id, "position", "x", now.x(), at);
        store.set(id, "position", "y", now.y(), at);
        store.set(id, "position", "heading", now.heading(), at);
        store.set(id, "position", "area", now.area(), at);
        store.set(id, "state", "state", now.state(), at);
        store.set(id, "state", "detect", now.detect(), at);
        store.set(id, "state", "obstacle", kind(now.detect()) == null ? null : kind(now.detect()).name(), at);
        store.set(id, "cart", "cart", now.cart(), at);
        store.set(id, "cart", "carrying", now.cart() != null, at);
        RobotAnswer.Mission m = now.mission();
        store.set(id, "mission", "id", m == null ? null : m.id(), at);
        store.set(id, "mission", "type", m == null ? null : m.type(), at);
        store.set(id, "mission", "state", m == null ? null : m.state(), at);
        store.set(id, "mission", "reason", m == null ? null : m.reason(), at);
        store.set(id, "mission", "goalX", m == null ? null : m.goalX(), at);
        store.set(id, "mission", "goalY", m == null ? null : m.goalY(), at);
        store.set(id, "counters", "nearMisses", now.nearMisses(), at);
        store.set(id, "counters", "deadlocks", now.deadlocks(), at);

        List<BrainIoTEvent> events = new ArrayList<>(2);
        if (before == null || before.x() != now.x() || before.y() != now.y()) {
            RobotPositionChanged e = robotEvent(new RobotPositionChanged(), id, at);
            e.x = now.x();
            e.y = now.y();
            e.heading = now.heading();
            e.area = now.area();
            e.state = now.state();
            e.previousX = before == null ? null : before.x();
            e.previousY = before == null ? null : before.y();
            events.add(e);
        }
        int detectBefore = before == null ? 0 : before.detect();
        if (detectBefore != now.detect()) {
            if (detectBefore != 0) {
                ObstacleCleared e = robotEvent(new ObstacleCleared(), id, at);
                e.kind = kind(detectBefore);
                e.x = now.x();
                e.y = now.y();
                events.add(e);
            }
            if (now.detect() != 0) {
                ObstacleDetected e = robotEvent(new ObstacleDetected(), id, at);
                e.kind = kind(now.detect());
                e.detect = now.detect();
                e.x = now.x();
                e.y = now.y();
                e.heading = now.heading();
                events.add(e);
            }
        }
        if (before != null && !Objects.equals(before.cart(), now.cart())) {
            if (before.cart() != null) {
                CartPlaced e = robotEvent(new CartPlaced(), id, at);
                e.cartId = before.cart();
                e.x = now.x();
                e.y = now.y();
                events.add(e);
            }
            if (now.cart() != null) {
                CartLifted e = robotEvent(new CartLifted(), id, at);
                e.cartId = now.cart();
                e.x = now.x();
                e.y = now.y();
                events.add(e);
            }
        }
        return events;
    }

    /** The event of a mission that ended. */
    static RobotEvent missionEnded(String robotId, RobotAnswer.Mission m, Instant at) {
        if ("finished".equals(m.state())) {
            MissionFinished e = robotEvent(new MissionFinished(), robotId, at);
            e.missionId = m.id();
            e.missionType = m.type();
            e.goalX = m.goalX();
            e.goalY = m.goalY();
            return e;
        }
        MissionFailed e = robotEvent(new MissionFailed(), robotId, at);
        e.missionId = m.id();
        e.missionType = m.type();
        e.reason = m.reason();
        e.goalX = m.goalX();
        e.goalY = m.goalY();
        return e;
    }

    static List<BrainIoTEvent> door(DeviceStore store, DoorAnswer before, DoorAnswer now, Instant at) {
        String id = now.id();
        store.set(id, "position", "x", now.x(), at);
        store.set(id, "position", "y", now.y(), at);
        store.set(id, "door", "state", now.state(), at);
        store.set(id, "door", "open", now.data() == 1.0, at);
        store.set(id, "door", "stepsLeft", now.stepsLeft(), at);
        if (before != null && before.state().equals(now.state())) {
            return List.of();
        }
        DoorStateChanged e = new DoorStateChanged();
        e.doorId = id;
        e.state = now.state();
        e.previousState = before == null ? null : before.state();
        e.x = now.x();
        e.y = now.y();
        e.timestamp = at;
        return List.of(e);
    }

    static ObstacleKind kind(int detect) {
        return switch (detect) {
            case 1 -> ObstacleKind.ROBOT;
            case 2 -> ObstacleKind.DOOR;
            default -> null;
        };
    }

    private static <E extends RobotEvent> E robotEvent(E event, String robotId, Instant at) {
        event.robotId = robotId;
        event.timestamp = at;
        return event;
    }
}
