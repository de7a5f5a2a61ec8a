package eu.brain.iot.eventing.impl;

import java.util.Map;
import java.util.function.Consumer;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;

/**
 * The events still queued for a forwarder when it goes away (its node left the fabric, or no longer takes them):
 * published again, never waiting, to whoever takes them now (a local behaviour, another node, or the unhandled-event
 * policy, which holds them for the behaviour it installs). An event that finds every queue full is counted as
 * discarded. Runs on the thread that retires the forwarder's queue (a delivery worker, or a publisher that met the
 * closed queue); keeps no state.
 */
final class Orphans implements Consumer<Envelope> {

    private final EventBus bus;
    private final Logger log;

    Orphans(EventBus bus, Logger log) {
        this.bus = bus;
        this.log = log;
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
