package eu.brain.iot.edge.api;

import java.util.List;
import java.util.Map;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * What one node's edge knows of the robots and doors it owns, published every poll period when the fleet is shared
 * between the nodes of a fabric (the edge's {@code share} is not {@code all}), and for one device alone as soon as it
 * changed, ahead of the events of the change: a report names all or some of the node's devices, and a receiver takes
 * those it names. Every edge consumes the reports of the other nodes, so each node's device model shows the whole
 * fleet, each device with the node that owns it (a behaviour that coordinates robots of several nodes reads them all
 * there), while only the owner polls a device and sends it commands.
 * <p>
 * Each entry of {@link #devices} is a map with the keys {@code id}, {@code kind} ({@code robot} or {@code door}),
 * {@code status} (a {@code ResourceStatus} name of the device model), {@code lastPoll} (epoch milliseconds of the
 * device's last answer, absent before the first), {@code reason} (why the status is not OK, absent otherwise) and
 * {@code values}: resource values by service, then by resource name, as the owner's device model holds them. Plain
 * maps and lists, so that a report crosses the fabric's wire and is converted back on any node unchanged.
 */
public class DeviceReport extends BrainIoTEvent {

    /** The reporting node's name (its edge's node name). */
    public String node;
    /** Devices this node owns, all of them or those that changed, one map each (keys above). */
    public List<Map<String, Object>> devices;
}
