package eu.brain.iot.edge.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A robot or a door left the edge's device model: the fleet the edge polls no longer has it (after a change of
 * {@code fleet.url}, the new fleet's inventory does not list it) or the edge's configuration no longer names it.
 * The last event about the device: the edge neither polls it nor publishes anything more about it (in particular
 * no {@link DeviceRecovered} after a {@link DeviceUnreachable}) until a fleet or a configuration brings it back,
 * and then as a new device, first announced like any other.
 */
public class DeviceRemoved extends BrainIoTEvent {

    /** The robot or door id. */
    public String deviceId;
    /** {@code robot} or {@code door}. */
    public String deviceKind;
    /**
     * Why, for example {@code not in the fleet at http://127.0.0.1:8090/ (GET / lists 2 robots, 1 doors)} or
     * {@code not in the configuration eu.brain.iot.edge any more (robots, doors)}.
     */
    public String reason;
}
