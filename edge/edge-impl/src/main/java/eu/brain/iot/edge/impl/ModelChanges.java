package eu.brain.iot.edge.impl;

import java.time.Instant;

/**
 * What the {@link DeviceStore} tells about each change of a provider, after it made it and after the resource
 * listeners (SSE) heard of each changed resource: the edge's events are derived from these ({@link EdgeEvents}).
 * Called on the fleet thread, in the order of the changes.
 */
interface ModelChanges {

    /**
     * A poll brought new values.
     *
     * @param before the answer the values came from until now, {@code null} the first time
     */
    void answered(String providerId, DeviceAnswer before, DeviceAnswer now, Instant at);

    /** The device stopped answering: its resources are {@code UNREACHABLE} now. */
    void unreachable(String providerId, DeviceKind kind, String reason, int failures);

    /** The device answers again after it was unreachable for {@code downMillis}. */
    void recovered(String providerId, DeviceKind kind, long downMillis);

    /**
     * The device is polled at another fleet URL from now on ({@code fleet.url} changed): what was known of it came
     * from the old fleet, and its next answer is taken as its first.
     */
    void moved(String providerId);

    /**
     * The provider left the model: the configuration no longer names it, the fleet's inventory no longer lists it
     * (or, for a cart or the map, the fleet's world no longer holds it).
     *
     * @param reason why, for the event and the log
     */
    void removed(String providerId, DeviceKind kind, String reason);
}
