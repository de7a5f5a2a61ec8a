package eu.brain.iot.bms.monitoring.api;

import org.osgi.dto.DTO;

/** Counters of the Behaviour Management Service since it started. */
public class ManagerCounters extends DTO {
    /** Unhandled events the bus put to the BMS. */
    public long unhandledEvents;
    /** Of those, events the BMS had the bus hold. */
    public long heldEvents;
    /** Searches of the repositories. */
    public long searches;
    /** Installs that succeeded. */
    public long installs;
    /** Install attempts that failed. */
    public long installFailures;
    /** Types for which no repository had a behaviour. */
    public long notFound;
    /** Held events given up on (install failed past its deadline, operator removal, not taken). */
    public long discardedEvents;
    /** Alert events published. */
    public long alerts;
}
