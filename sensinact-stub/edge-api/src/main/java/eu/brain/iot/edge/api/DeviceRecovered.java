package eu.brain.iot.edge.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** A device that was {@link DeviceUnreachable} answers again. */
public class DeviceRecovered extends BrainIoTEvent {

    public String deviceId;
    public String deviceKind;
    /** How long it was unreachable, in milliseconds. */
    public long downMillis;
}
