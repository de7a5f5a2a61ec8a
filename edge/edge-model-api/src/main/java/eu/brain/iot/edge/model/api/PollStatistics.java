package eu.brain.iot.edge.model.api;

import org.osgi.dto.DTO;

/**
 * The edge's polling and publishing counters since it started (a snapshot). A poll is <em>on time</em> when it was
 * answered and its request went out within the poll period &plusmn; 10% of the previous answered poll's request.
 * Since 1.1.
 */
public class PollStatistics extends DTO {
    /** The fleet's REST base URL, or {@code null} before the edge is configured. */
    public String fleetUrl;
    public long sent;
    public long answered;
    public long failed;
    /** Polls not sent because the device's previous poll was still unanswered. */
    public long skipped;
    public long onTime;
    public long late;
    /** The time the counters cover, in seconds. */
    public double seconds;
    /** Median and 99th percentile of |interval &minus; period| over answered polls, milliseconds. */
    public double deviationP50Millis;
    public double deviationP99Millis;
    /** Edge events waiting in the edge's outbox now, because the bus refused them (a behaviour's queue was full). */
    public int eventsWaiting;
    /** Times the bus refused one of the edge's events (an event retried counts again). */
    public long eventsRefused;
    /** Robot positions replaced by a newer one while they waited (never obstacle, cart, door, mission, reachability or command events). */
    public long positionsCoalesced;
}
