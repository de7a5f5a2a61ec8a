package eu.brain.iot.federation.api;

import java.util.List;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A node's lease on the fleet's devices, renewed every {@code renew.ms} by the node's lease manager and routed to
 * every other node's lease manager through the fabric. Other nodes take a node's devices over once its lease has not
 * been renewed for {@code lease.ms}; a node commands only the devices its last lease listed.
 */
public class DeviceLease extends BrainIoTEvent {

    /** The node that holds the lease (its {@code fabric.node.name}). */
    public String node;
    /** The devices its configuration gives it (its share), which it takes back when it is alive. */
    public List<String> share;
    /** The devices it owns now: polls and commands. */
    public List<String> owned;
    /** How long the lease holds after it was sent, in milliseconds of wall time. */
    public long leaseMillis;
}
