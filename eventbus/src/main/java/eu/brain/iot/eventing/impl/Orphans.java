package eu.brain.iot.eventing.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.impl.EventHold.Held;

/**
 * The events queued for a forwarder when it goes away (its node left the fabric, or no longer takes them). Those
 * queued when it leaves the route table keep their place ({@link #held}: the bus hands them over in the same step);
 * one a publisher routes to it just after is published again here, waiting for room as that publisher would, to
 * whoever takes it now (a local behaviour, another node, or the unhandled-event policy, which holds it for the
 * behaviour it installs), by the route table published without that forwarder; one left when the bus closes, never
 * waiting. An event that finds no room is counted as discarded. Runs on the publisher's thread or the one that
 * retires the forwarder's queue; keeps no state.
 */
final class Orphans {

    private final EventBus bus;
    private final Object tableLock;
    private final Logger log;

    /**
     * @param tableLock the lock under which the bus closes a forwarder and publishes the route table without it
     */
    Orphans(EventBus bus, Object tableLock, Logger log) {
        this.bus = bus;
        this.tableLock = tableLock;
        this.log = log;
    }

    /** A forwarder's queued events as held events, to join the hold in their order (see the bus's removal). */
    static List<Held> held(List<Envelope> queued) {
        long now = System.currentTimeMillis();
        List<Held> held = new ArrayList<>(queued.size());
        for (Envelope e : queued) {
            // a shared snapshot is read by the event's other consumers: the one that takes it over gets its own
            Object own = e.exclusive ? e.payload : copy(e.payload);
            held.add(new Held(own, own instanceof BrainIoTEvent ? own.getClass() : null, e.counters, now, null));
        }
        return held;
    }

    @SuppressWarnings("unchecked")
    private static Object copy(Object payload) {
        return payload instanceof BrainIoTEvent event ? EventCopier.copyEvent(event)
                : EventMaps.copyMap((Map<String, ?>) payload);
    }

    /**
     * Publish an event again, by the table without the forwarder that left.
     *
     * @param mayWait whether to wait for room as its publisher would ({@link Envelope#publisherWaits}), up to the
     *        bus's overflow timeout; false on a delivery thread
     */
    @SuppressWarnings("unchecked")
    void publishAgain(Envelope e, boolean mayWait) {
        synchronized (tableLock) {
            // Taking the lock waits for the table without the forwarder that left: published again by the table
            // the publisher routed with, the event would find that forwarder closed and come back here, endlessly.
        }
        boolean accepted;
        try {
            if (!mayWait) {
                accepted = e.payload instanceof BrainIoTEvent event ? bus.tryDeliver(event)
                        : bus.tryDeliver(e.type(), (Map<String, Object>) e.payload);
            } else if (e.payload instanceof BrainIoTEvent event) {
                bus.deliver(event);
                accepted = true;
            } else {
                bus.deliver(e.type(), (Map<String, Object>) e.payload);
                accepted = true;
            }
        } catch (EventBusOverflowException full) {
            accepted = false;
        }
        if (!accepted) {
            e.counters.discarded.increment();
            log.warn("An event of type {} queued for a node that left the fabric found every queue full when it was "
                    + "published again; it was discarded and counted as 'discarded' (bus:stats).", e.type());
        }
    }
}
