package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.Objects;

import eu.brain.iot.edge.api.CartLifted;
import eu.brain.iot.edge.api.CartPlaced;
import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceRemoved;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.ObstacleCleared;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.ObstacleKind;
import eu.brain.iot.edge.api.RobotEvent;
import eu.brain.iot.edge.api.RobotPositionChanged;

/**
 * The edge's events, derived from the changes of the device model ({@link ModelChanges}) and sent through the
 * {@link Outbox}: what a robot or door did between two answers, reachability, a device's removal, and (through the
 * {@link MissionTracker}) mission ends. Called on the fleet thread only; keeps no state but the tracker's.
 */
final class EdgeEvents implements ModelChanges {

    private final Outbox outbox;
    private final MissionTracker missions;

    EdgeEvents(Outbox outbox, MissionTracker missions) {
        this.outbox = outbox;
        this.missions = missions;
    }

    @Override
    public void answered(String providerId, DeviceAnswer before, DeviceAnswer now, Instant at) {
        now.announce(this, before, at);
    }

    @Override
    public void unreachable(String providerId, DeviceKind kind, String reason, int failures) {
        DeviceUnreachable e = new DeviceUnreachable();
        e.deviceId = providerId;
        e.deviceKind = kind.label;
        e.reason = reason;
        e.failures = failures;
        outbox.publish(e);
    }

    @Override
    public void recovered(String providerId, DeviceKind kind, long downMillis) {
        DeviceRecovered e = new DeviceRecovered();
        e.deviceId = providerId;
        e.deviceKind = kind.label;
        e.downMillis = downMillis;
        outbox.publish(e);
    }

    @Override
    public void moved(String providerId) {
        missions.forget(providerId); // mission ids are the old fleet's: none of its ends is news at the new one
    }

    @Override
    public void removed(String providerId, DeviceKind kind, String reason) {
        missions.forget(providerId);
        if (kind != DeviceKind.ROBOT && kind != DeviceKind.DOOR) {
            return; // carts and the map have no bus events of their own (WorldReader)
        }
        // the last word on the device: a behaviour that was told DeviceUnreachable learns it will hear no recovery
        DeviceRemoved e = new DeviceRemoved();
        e.deviceId = providerId;
        e.deviceKind = kind.label;
        e.reason = reason;
        outbox.publish(e);
    }

    /** @param before the previous answer, {@code null} the first time (then only the position is announced) */
    void robot(RobotAnswer before, RobotAnswer now, Instant at) {
        String id = now.id();
        if (before == null || before.x() != now.x() || before.y() != now.y()) {
            RobotPositionChanged e = robotEvent(new RobotPositionChanged(), id, at);
            e.x = now.x();
            e.y = now.y();
            e.heading = now.heading();
            e.area = now.area();
            e.state = now.state();
            e.previousX = before == null ? null : before.x();
            e.previousY = before == null ? null : before.y();
            outbox.publish(e);
        }
        int detectBefore = before == null ? 0 : before.detect();
        if (detectBefore != now.detect()) {
            if (detectBefore != 0) {
                ObstacleCleared e = robotEvent(new ObstacleCleared(), id, at);
                e.kind = kind(detectBefore);
                e.x = now.x();
                e.y = now.y();
                outbox.publish(e);
            }
            if (now.detect() != 0) {
                ObstacleDetected e = robotEvent(new ObstacleDetected(), id, at);
                e.kind = kind(now.detect());
                e.detect = now.detect();
                e.x = now.x();
                e.y = now.y();
                e.heading = now.heading();
                outbox.publish(e);
            }
        }
        if (before != null && !Objects.equals(before.cart(), now.cart())) {
            if (before.cart() != null) {
                CartPlaced e = robotEvent(new CartPlaced(), id, at);
                e.cartId = before.cart();
                e.x = now.x();
                e.y = now.y();
                outbox.publish(e);
            }
            if (now.cart() != null) {
                CartLifted e = robotEvent(new CartLifted(), id, at);
                e.cartId = now.cart();
                e.x = now.x();
                e.y = now.y();
                outbox.publish(e);
            }
        }
        missions.track(id, before, now, at);
    }

    void door(DoorAnswer before, DoorAnswer now, Instant at) {
        if (before != null && before.state().equals(now.state())) {
            return;
        }
        DoorStateChanged e = new DoorStateChanged();
        e.doorId = now.id();
        e.state = now.state();
        e.previousState = before == null ? null : before.state();
        e.x = now.x();
        e.y = now.y();
        e.timestamp = at;
        outbox.publish(e);
    }

    static ObstacleKind kind(int detect) {
        return switch (detect) {
            case 1 -> ObstacleKind.ROBOT;
            case 2 -> ObstacleKind.DOOR;
            default -> null;
        };
    }

    static <E extends RobotEvent> E robotEvent(E event, String robotId, Instant at) {
        event.robotId = robotId;
        event.timestamp = at;
        return event;
    }
}
