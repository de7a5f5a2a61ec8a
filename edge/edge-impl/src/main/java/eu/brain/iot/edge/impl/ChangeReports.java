package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.function.Consumer;

import eu.brain.iot.edge.api.DeviceReport;

/**
 * A shared fleet's device changes reported to the other nodes at once: when a poll brings new values of a device this
 * node owns, or the device stops answering or answers again, a {@link DeviceReport} of that device alone is published
 * before the events derived from the change. The fabric keeps one publisher's events in order, so a behaviour on
 * another node that acts on such an event (the robot behaviour that drives the fleet looks at the robot's new state
 * when it hears of it) finds that state in its own node's device model, not the one of the last full report, which
 * is up to a poll period older. The full report every poll period ({@link Edge}) stays: it keeps every device fresh
 * on the other nodes while nothing changes.
 * <p>
 * Called on the fleet thread only, as every {@link ModelChanges}; keeps no state.
 */
final class ChangeReports implements ModelChanges {

    private final ModelChanges events;
    private final Consumer<String> reportDevice;

    /**
     * @param events       where the changes go next: the edge's events
     * @param reportDevice publishes a report of the one device named (nothing when the fleet is not shared)
     */
    ChangeReports(ModelChanges events, Consumer<String> reportDevice) {
        this.events = events;
        this.reportDevice = reportDevice;
    }

    @Override
    public void answered(String providerId, DeviceAnswer before, DeviceAnswer now, Instant at) {
        reportDevice.accept(providerId);
        events.answered(providerId, before, now, at);
    }

    @Override
    public void unreachable(String providerId, DeviceKind kind, String reason, int failures) {
        reportDevice.accept(providerId);
        events.unreachable(providerId, kind, reason, failures);
    }

    @Override
    public void recovered(String providerId, DeviceKind kind, long downMillis) {
        reportDevice.accept(providerId);
        events.recovered(providerId, kind, downMillis);
    }

    @Override
    public void moved(String providerId) {
        events.moved(providerId);
    }

    @Override
    public void removed(String providerId, DeviceKind kind, String reason) {
        events.removed(providerId, kind, reason);
    }
}
