package eu.brain.iot.edge.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A device that was {@link DeviceUnreachable} answers again: at the same fleet, or at the one the edge was
 * configured to since ({@code fleet.url} changed: the device keeps its id and is told recovered when the new fleet
 * answers for it).
 */
public class DeviceRecovered extends BrainIoTEvent {

    public String deviceId;
    public String deviceKind;
    /** How long it was unreachable, in milliseconds (since the first report, whichever fleet it was at then). */
    public long downMillis;
}
