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
}
