package eu.brain.iot.edge.impl;

import java.net.URI;
import java.util.ArrayDeque;

/** One polled device's schedule and health. Owned by the fleet thread: no other thread touches it. */
final class PolledDevice {

    /** Mission ids already reported as ended, so that no end is announced twice. */
    private static final int REMEMBERED_MISSIONS = 64;

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
     * Mission ends seen while the robot's history is being asked about an earlier mission: announced after it,
     * so that ends come out in the order the missions ended. {@code null} when no history query is pending.
     */
    java.util.List<RobotAnswer.Mission> heldEnds;

    /** The last answer, a {@link RobotAnswer} or a {@link DoorAnswer}; {@code null} before the first. */
    Object last;
    /**
     * The body {@link #last} was parsed from ({@code null} before the first): an answer with the same bytes is not
     * parsed again. Handed to the HTTP thread of the next poll as an immutable array, never changed in place.
     */
    byte[] lastBody;
    private final ArrayDeque<Long> reportedMissions = new ArrayDeque<>();

    PolledDevice(String id, DeviceKind kind, URI stateUri) {
        this.id = id;
        this.kind = kind;
        this.stateUri = stateUri;
    }

    /** @return true the first time a mission id is reported */
    boolean firstReport(long missionId) {
        if (reportedMissions.contains(missionId)) {
            return false;
        }
        if (reportedMissions.size() == REMEMBERED_MISSIONS) {
            reportedMissions.removeFirst();
        }
        reportedMissions.addLast(missionId);
        return true;
    }
}
