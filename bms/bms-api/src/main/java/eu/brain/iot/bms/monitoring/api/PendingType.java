package eu.brain.iot.bms.monitoring.api;

import java.util.List;

import org.osgi.dto.DTO;

/** One event type the BMS is deciding about. */
public class PendingType extends DTO {
    /** The event type. */
    public String eventType;
    /** The types searched for: the event's type, then its supertypes and interfaces. */
    public List<String> searched;
    /**
     * {@code SEARCHING}, {@code INSTALLING}, {@code RETRY_WAIT} (its events are held), or, its events counted as
     * unhandled until {@link #until}: {@code NOT_FOUND}, {@code REMOVED_BY_OPERATOR}, {@code GAVE_UP},
     * {@code NOT_TAKEN} (the installed behaviour does not take these events, e.g. its filter).
     */
    public String state;
    /** The behaviour chosen for it (symbolic name and version), if any. */
    public String behaviour;
    /** Events of the type held by the bus now. */
    public int heldEvents;
    /** Events of the type the BMS answered "unhandled" for in this state. */
    public long unhandledEvents;
    /** When this type's first unhandled event came (milliseconds since the epoch). */
    public long since;
    /** Install attempts so far. */
    public int attempt;
    /** When the state ends: next retry, or end of the "not searched again" period (ms since the epoch); 0: none. */
    public long until;
    /** The last failure's reason, if any. */
    public String lastReason;
}
