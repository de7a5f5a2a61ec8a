package eu.brain.iot.federation.impl;

import eu.brain.iot.eventing.spi.EventForwarder;
import eu.brain.iot.eventing.spi.RemoteEvents;

/**
 * What a fabric node needs from the node it runs in: the bus's delivery of events from other nodes, and the
 * registration of forwarders with the bus. In a framework these are OSGi services ({@link FabricComponent}); in
 * tests, the bus core itself.
 */
public interface Host {

    /** @return the bus's delivery of events from other nodes */
    RemoteEvents remoteEvents();

    /**
     * Have the bus route events of these types (and filter) to a forwarder of the destination.
     *
     * @return closing it takes the forwarder away from the bus
     */
    AutoCloseable addForwarder(String destination, InterestEntry entry, EventForwarder forwarder);

    /** Log a fact an operator should see. */
    void warn(String message, Object... args);

    /** Log a fact. */
    void info(String message, Object... args);
}
