package eu.brain.iot.eventing.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.impl.EventHold.Held;
import eu.brain.iot.eventing.impl.RouteTable.Route;

/**
 * The events queued for a forwarder when it goes away (its node left the fabric, or no longer takes them). Those
 * queued when it leaves the route table keep their place ({@link #held}: the bus hands them over in the same step);
 * one a publisher routes to it just after is published again here, by the route table without that forwarder,
 * waiting for room as that publisher would; one left when the bus closes, never waiting. Either way an event goes
 * to whoever takes it now (a local behaviour, another node, or the unhandled-event policy, which holds it for the
 * behaviour it installs) but never again to a consumer it reached already: when others took it too, only the
 * consumers that take it now and did not have it get it. An event that finds no room is counted as discarded.
 * Runs on the publisher's thread or the one that retires the forwarder's queue; keeps no state.
 */
final class Orphans {

    private final AsyncEventBus bus;
    private final Logger log;

    Orphans(AsyncEventBus bus, Logger log) {
        this.bus = bus;
        this.log = log;
    }

    /** A forwarder's queued events as held events, to join the hold in their order (see the bus's removal). */
    static List<Held> held(List<Envelope> queued) {
        long now = System.currentTimeMillis();
        List<Held> held = new ArrayList<>(queued.size());
        for (Envelope e : queued) {
            // a shared snapshot is read by the event's other consumers: the one that takes it over gets its own
            Object own = e.exclusive ? e.payload : copy(e.payload);
            held.add(new Held(own, own instanceof BrainIoTEvent ? own.getClass() : null, e.counters, now, null,
                    e.reached));
        }
        return held;
    }

    @SuppressWarnings("unchecked")
    private static Object copy(Object payload) {
        return payload instanceof BrainIoTEvent event ? EventCopier.copyEvent(event)
                : EventMaps.copyMap((Map<String, ?>) payload);
    }

    /**
     * Publish an event again, by the table without the forwarder that left: read once the bus has published it, or
     * the event would find that forwarder closed and come back here, endlessly.
     *
     * @param mayWait whether to wait for room as its publisher would ({@link Envelope#publisherWaits}), up to the
     *        bus's overflow timeout; false on a delivery thread
     */
    @SuppressWarnings("unchecked")
    void publishAgain(Envelope e, boolean mayWait) {
        RouteTable table = bus.settledRoutes();
        boolean accepted;
        try {
            if (reachedOthers(e)) {
                Object own = copy(e.payload);
                Route route = bus.routeOf(table, own instanceof BrainIoTEvent ? own.getClass() : null, e.type(),
                        null);
                ConsumerChannel[] to = EventHold.without(route.targets(own), e.reached);
                accepted = to.length == 0 || bus.send(to, route, own, mayWait, null);
            } else if (!mayWait) {
                accepted = e.payload instanceof BrainIoTEvent event ? bus.tryDeliver(event)
                        : bus.tryDeliver(e.type(), (Map<String, Object>) e.payload);
            } else {
                if (e.payload instanceof BrainIoTEvent event) {
                    bus.deliver(event); // waits for room, throws when there is none
                } else {
                    bus.deliver(e.type(), (Map<String, Object>) e.payload);
                }
                accepted = true;
            }
        } catch (EventBusOverflowException full) {
            accepted = false;
        }
        if (!accepted) {
            e.counters.discarded.increment();
            log.warn("An event of type {} queued for a node that left the fabric found every queue full when it was "
                    + "published again; it was discarded and counted as 'discarded' (bus:stats). A consumer that keeps "
                    + "its queue full needs looking at (bus:behaviours), or raise queue.capacity or "
                    + "overflow.timeout.ms in the configuration {}.", e.type(), BusConfig.PID);
        }
    }

    /** Whether a consumer still running took the event besides the one that left. */
    private static boolean reachedOthers(Envelope e) {
        for (ConsumerChannel c : e.reached) {
            if (!c.isClosed()) {
                return true;
            }
        }
        return false;
    }
}
