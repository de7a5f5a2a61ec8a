package eu.brain.iot.eventing.impl;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Function;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.impl.EventHold.Held;
import eu.brain.iot.eventing.impl.RouteTable.Route;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * Puts an unhandled event to the {@link UnhandledEventPolicy}: once per event, never from inside the policy itself
 * (an event the policy publishes follows the bus's own rules), and a failing or silent policy counts as
 * {@link Disposition#LAST_RESORT}, its first failure logged.
 * <p>
 * Threads: called by publishers (and by the thread that retires a forwarder), never under the bus's lock; the
 * thread-local flag and the atomic flag are its only state.
 */
final class PolicyAsker {

    /** Set while this thread is inside the policy: an event it publishes there is not put to the policy again. */
    private static final ThreadLocal<Boolean> ASKING = ThreadLocal.withInitial(() -> Boolean.FALSE);

    private final Logger log;
    private final AtomicBoolean failureLogged = new AtomicBoolean();

    PolicyAsker(Logger log) {
        this.log = log;
    }

    /**
     * The policy's answer for each type among these held events (asked once per type); without a policy, the bus's
     * own rules ({@link Disposition#LAST_RESORT}) for every type.
     */
    Map<String, Disposition> askPerType(UnhandledEventPolicy current, List<Held> events, Function<Held, Route> route) {
        Map<String, Disposition> decided = new HashMap<>();
        for (Held h : events) {
            decided.computeIfAbsent(h.counters().eventType,
                    t -> current == null ? Disposition.LAST_RESORT : ask(current, route.apply(h), h.snapshot()));
        }
        return decided;
    }

    /** @param snapshot the bus's snapshot of the event: an event object, or a map for an untyped event */
    @SuppressWarnings("unchecked")
    Disposition ask(UnhandledEventPolicy current, Route route, Object snapshot) {
        if (ASKING.get()) {
            return Disposition.LAST_RESORT;
        }
        ASKING.set(Boolean.TRUE);
        try {
            Disposition d = current.unhandled(route.counters().eventType, route.typeNames(),
                    () -> snapshot instanceof Map<?, ?> map ? EventMaps.copyMap((Map<String, ?>) map)
                            : EventMaps.toMap(snapshot));
            return d == null ? Disposition.LAST_RESORT : d;
        } catch (RuntimeException e) {
            if (failureLogged.compareAndSet(false, true)) {
                log.error("The unhandled-event policy {} failed on an event of type {}; such events follow the "
                        + "bus's own rules (consumers of last resort, else counted as unhandled). Further failures "
                        + "are not logged.", current.getClass().getName(), route.counters().eventType, e);
            }
            return Disposition.LAST_RESORT;
        } finally {
            ASKING.set(Boolean.FALSE);
        }
    }
}
