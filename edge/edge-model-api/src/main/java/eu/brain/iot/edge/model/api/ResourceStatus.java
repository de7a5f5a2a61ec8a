package eu.brain.iot.edge.model.api;

/** How far a resource's value can be trusted. */
public enum ResourceStatus {
    /** The last poll of the device answered: the value is current. */
    OK,
    /** The last poll failed: the value is what the device said before, and may be out of date. */
    STALE,
    /** The device failed several polls in a row; the edge keeps trying with backoff. */
    UNREACHABLE
}
