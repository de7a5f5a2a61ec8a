package eu.brain.iot.eventing.monitoring.api;

import org.osgi.dto.DTO;

/** Counters of one event type since the bus started. */
public class EventTypeStatistics extends DTO {
    /** The fully qualified event type name. */
    public String eventType;
    /** Events of this type accepted by {@code deliver}. */
    public long published;
    /** Deliveries completed without exception (one per consumer per event). */
    public long delivered;
    /** Deliveries whose consumer threw. */
    public long failed;
    /** Events that no consumer took, not even a consumer of last resort (held events given up included). */
    public long unhandled;
    /** Deliveries dropped because their consumer went away while they were queued. */
    public long discarded;
    /**
     * Events of this type held now by the bus for an unhandled-event policy, waiting for a behaviour that
     * consumes them (already counted in {@link #published}). Since 1.1.
     */
    public long held;
}
