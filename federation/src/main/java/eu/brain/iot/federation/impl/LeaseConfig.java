package eu.brain.iot.federation.impl;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/**
 * The device lease manager's configuration (PID {@value #PID}); without it there is no lease manager and the edge
 * owns what its own configuration gives it.
 */
@ObjectClassDefinition(name = "BRAIN-IoT fabric device leases", description = "Moves the ownership of the fleet's "
        + "devices between the nodes of a fabric: a node's devices go to the others when its lease lapses")
public @interface LeaseConfig {

    /** The configuration PID. */
    String PID = "eu.brain.iot.federation.lease";

    @AttributeDefinition(description = "How long a lease holds after it was sent (ms of wall time): a node silent for "
            + "this long loses its devices to the others")
    long lease_ms() default 2000;

    @AttributeDefinition(description = "How often a node renews its lease (ms); well under lease.ms")
    long renew_ms() default 500;

    @AttributeDefinition(description = "How long a node that starts or comes back into its fabric leaves a device "
            + "that no node has claimed yet (in no node's share, held by no node heard) to the node whose share holds "
            + "it, so that nodes starting a few seconds apart each get their own share first (ms; at least lease.ms). "
            + "A device of a node that died is taken at once")
    long join_grace_ms() default 10000;
}
