package eu.brain.iot.edge.impl;

import java.net.URI;

/** One polled device's schedule and health. Owned by the fleet thread: no other thread touches it. */
final class PolledDevice {

    final String id;
    final DeviceKind kind;
    final URI stateUri;

    /** When the next poll is due ({@link System#nanoTime()}). */
    long dueNanos;
    /** Counts the times the next poll was (re)scheduled: an older entry in the fleet's due queue is stale. */
    int round;
    boolean inFlight;
    boolean removed;
    /** Request time of the last answered poll, or -1 when the last poll was not answered. */
    long lastAnsweredSentNanos = -1;

    int failures;
    boolean unreachable;
    long unreachableSinceMillis;
    long lastWarnMillis;
    int warningsSuppressed;

    /**
     * The body of the answer the device's values came from ({@code null} before the first): an answer with the
     * same bytes is not parsed again. Handed to the HTTP thread of the next poll as an immutable array, never
     * changed in place.
     */
    byte[] lastBody;

    PolledDevice(String id, DeviceKind kind, URI stateUri) {
        this.id = id;
        this.kind = kind;
        this.stateUri = stateUri;
    }

    /**
     * This device polled at another fleet URL ({@code fleet.url} changed): a schedule of its own and no answer yet
     * (this one is dropped: an answer still on its way from the old fleet must not count), but an unreachable device
     * stays unreachable, since it went down: the model tells its recovery when the new fleet answers for it, and
     * tells nothing twice when it does not.
     *
     * @param unreachableAfter failed polls that make a device unreachable: its backoff starts over from the first step
     */
    PolledDevice successor(URI newStateUri, int unreachableAfter) {
        removed = true;
        PolledDevice next = new PolledDevice(id, kind, newStateUri);
        if (unreachable) {
            next.unreachable = true;
            next.failures = unreachableAfter;
            next.unreachableSinceMillis = unreachableSinceMillis;
        }
        return next;
    }
}
