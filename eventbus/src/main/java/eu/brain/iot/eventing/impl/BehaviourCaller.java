package eu.brain.iot.eventing.impl;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.spi.EventForwarder;

/**
 * Hands events to one behaviour: fetches the behaviour object on the first delivery, makes the behaviour's own
 * copy of each event (in its own bundle's class when it has one), calls {@code notify} and keeps the behaviour
 * alive when that throws.
 * <p>
 * Ownership: everything here belongs to the thread that currently holds the behaviour's {@link ConsumerChannel}'s
 * turn token (at most one at a time, see there): a delivery worker, or for a forwarder the publisher that took it; the hand-over between workers goes through the
 * channel's scheduling flag and the pool's run queue, which order the previous holder's writes before the next
 * holder's reads. Only {@link #delivered} and {@link #failures} are read by other threads (statistics), which
 * is why they are atomics written with ordered writes.
 */
final class BehaviourCaller {

    private final ConsumerSpec spec;
    private final Logger log;

    private final AtomicLong delivered = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();

    /** The behaviour object, fetched on the first delivery (a behaviour may need the bus to activate). */
    private Object behaviour;
    private final Map<Class<?>, Class<?>> ownClassOf = new HashMap<>();
    /** Kept in a field: a method reference written at the call site would be allocated for every event. */
    private final Function<Class<?>, Class<?>> ownClassFunction = this::ownClass;
    private final Map<String, Class<?>> ownClassByName = new HashMap<>();
    private final Set<String> failureLogged = new HashSet<>();

    BehaviourCaller(ConsumerSpec spec, Logger log) {
        this.spec = spec;
        this.log = log;
    }

    /** Deliver one event; a failure is counted (and logged once per event type), never thrown. */
    void call(Envelope envelope) {
        try {
            if (fetched() == null) {
                throw new IllegalStateException("the behaviour service is no longer available");
            }
            if (spec.forwarder()) {
                ((EventForwarder) behaviour).forward(envelope.type(), typeNames(envelope), toMap(envelope));
            } else if (spec.untyped()) {
                ((UntypedSmartBehaviour) behaviour).notify(envelope.type(), toMap(envelope));
            } else {
                @SuppressWarnings("unchecked")
                SmartBehaviour<BrainIoTEvent> typed = (SmartBehaviour<BrainIoTEvent>) behaviour;
                typed.notify(toTyped(envelope));
            }
            delivered.lazySet(delivered.get() + 1);
            envelope.counters.delivered.increment();
        } catch (OutOfMemoryError e) {
            throw e;
        } catch (Throwable t) {
            failed(envelope, t);
        } finally {
            envelope.consumed();
        }
    }

    /**
     * For a forwarder, on the thread of the publisher that holds its turn token: hand one event over if the
     * forwarder takes it without waiting ({@link EventForwarder#forwardNow}). A failure counts as in {@link #call}.
     *
     * @return {@code true} when the event was taken or failed (it is consumed); {@code false} when the forwarder
     *         did not take it (nothing happened: it is for {@link #call} on a delivery worker)
     */
    boolean forwardNow(Envelope envelope) {
        try {
            if (fetched() == null) {
                return false; // call() says so on a delivery worker
            }
            if (!((EventForwarder) behaviour).forwardNow(envelope.type(), typeNames(envelope), toMap(envelope))) {
                return false;
            }
            delivered.lazySet(delivered.get() + 1);
            envelope.counters.delivered.increment();
        } catch (OutOfMemoryError e) {
            throw e;
        } catch (Throwable t) {
            failed(envelope, t);
        }
        envelope.consumed();
        return true;
    }

    /** The behaviour object, fetched at the first delivery; {@code null} when its service is gone. */
    private Object fetched() {
        if (behaviour == null) {
            behaviour = spec.target().get();
        }
        return behaviour;
    }

    private void failed(Envelope envelope, Throwable t) {
        failures.lazySet(failures.get() + 1);
        envelope.counters.failed.increment();
        if (failureLogged.add(envelope.type())) {
            log.error("Smart behaviour {} (bundle {}) failed on an event of type {}; it keeps receiving "
                    + "events, and further failures on this type are counted in the bus statistics "
                    + "(Gogo: bus:stats) rather than logged.", spec.name(), spec.bundle(), envelope.type(), t);
        }
    }

    private static List<String> typeNames(Envelope envelope) {
        return envelope.typeNames != null ? envelope.typeNames : List.of(envelope.type());
    }

    /** Give the behaviour object back, if it was ever fetched; the caller is not used afterwards. */
    void releaseBehaviour() {
        if (behaviour != null) {
            behaviour = null;
            spec.target().release();
        }
    }

    long delivered() {
        return delivered.get();
    }

    long failures() {
        return failures.get();
    }

    @SuppressWarnings("unchecked")
    private Map<String, Object> toMap(Envelope envelope) {
        return envelope.payload instanceof Map<?, ?> map
                ? EventMaps.copyMap((Map<String, ?>) map)
                : EventMaps.toMap(envelope.payload);
    }

    @SuppressWarnings("unchecked")
    private BrainIoTEvent toTyped(Envelope envelope) {
        if (envelope.payload instanceof BrainIoTEvent event) {
            Class<?> own = ownClassOf.computeIfAbsent(event.getClass(), ownClassFunction);
            if (own == event.getClass()) {
                return envelope.exclusive ? event : EventCopier.copyEvent(event);
            }
            return (BrainIoTEvent) EventMaps.convert(event, own);
        }
        Class<?> own = ownClassByName.computeIfAbsent(envelope.type(), spec.classes());
        if (own == null && envelope.typeNames != null) {
            // an event from another node whose own class this bundle cannot see: the first supertype it consumes
            for (String name : envelope.typeNames) {
                if (spec.consumed().contains(name)) {
                    own = ownClassByName.computeIfAbsent(name, spec.classes());
                    break;
                }
            }
        }
        if (own == null) {
            throw new IllegalStateException("bundle " + spec.bundle() + " cannot load the event class "
                    + envelope.type() + " that it declares it consumes");
        }
        return (BrainIoTEvent) EventMaps.fromMap((Map<String, ?>) envelope.payload, own);
    }

    /** The class this behaviour's bundle sees under the event class's name; the event's own class if none. */
    private Class<?> ownClass(Class<?> eventClass) {
        Class<?> own = spec.classes().apply(eventClass.getName());
        return own == null ? eventClass : own;
    }
}
