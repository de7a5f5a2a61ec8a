package eu.brain.iot.edge.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The edge lost a robot or a door: it failed to answer several polls in a row. Published once; the edge keeps
 * polling it with backoff and publishes {@link DeviceRecovered} when it answers again, also when that is at another
 * fleet URL the edge was configured to meanwhile; or {@link DeviceRemoved} if the device leaves the edge's model
 * first (the new fleet does not have it, the configuration no longer names it).
 */
public class DeviceUnreachable extends BrainIoTEvent {

    /** The robot or door id. */
    public String deviceId;
    /** {@code robot} or {@code door}. */
    public String deviceKind;
    /** The last failure, for example {@code no answer within 1000 ms} or {@code HTTP 503: robot robot1 is offline}. */
    public String reason;
    /** Failed polls in a row when it was declared unreachable. */
    public int failures;
}
