package eu.brain.iot.eventing.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.impl.EventHold.Held;

/**
 * The events queued for a forwarder when it goes away (its node left the fabric, or no longer takes them). Those
 * queued when it leaves the route table keep their place ({@link #held}: the bus hands them over in the same step);
 * one a publisher routes to it just after, or one left when the bus closes, is published again here, never waiting,
 * to whoever takes it now (a local behaviour, another node, or the unhandled-event policy, which holds it for the
 * behaviour it installs). An event that finds every queue full is counted as discarded. Runs on the publisher's
 * thread or the one that retires the forwarder's queue; keeps no state.
 */
final class Orphans implements Consumer<Envelope> {

    private final EventBus bus;
    private final Logger log;

    Orphans(EventBus bus, Logger log) {
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
            held.add(new Held(own, own instanceof BrainIoTEvent ? own.getClass() : null, e.counters, now, null));
        }
        return held;
    }

    @SuppressWarnings("unchecked")
    private static Object copy(Object payload) {
        return payload instanceof BrainIoTEvent event ? EventCopier.copyEvent(event)
                : EventMaps.copyMap((Map<String, ?>) payload);
    }

    @Override
    @SuppressWarnings("unchecked")
    public void accept(Envelope e) {
        boolean accepted = e.payload instanceof BrainIoTEvent event ? bus.tryDeliver(event)
                : bus.tryDeliver(e.type(), (Map<String, Object>) e.payload);
        if (!accepted) {
            e.counters.discarded.increment();
            log.warn("An event of type {} queued for a node that left the fabric found every queue full when it was "
                    + "published again; it was discarded and counted as 'discarded' (bus:stats).", e.type());
        }
    }
}
