package eu.brain.iot.eventing.spi;

import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

import org.osgi.annotation.versioning.ConsumerType;

/**
 * Decides what the bus does with an event that no behaviour consumes (after filters). Registered as an OSGi
 * service by a Behaviour Management Service; the bus follows the highest-ranked one. Without any policy the bus
 * behaves as before: consumers of last resort, else counted as unhandled.
 * <p>
 * Threading: {@link #unhandled} and {@link #maxHeldEvents} are called on the publisher's thread, for every such
 * event, while the publisher waits for the answer (the bus holds none of its locks then): they must answer at once
 * (a map look-up), must not block, must not do I/O and must not publish on the bus (an event published from
 * within {@link #unhandled} is not put to the policy again: it follows the bus's own rules). Work such as
 * searching a repository belongs on the policy's own threads. An exception thrown here is logged once and the
 * event follows the bus's own rules ({@link Disposition#LAST_RESORT}); so does a {@code null} answer.
 * <p>
 * When the policy service goes away, the events it held follow the bus's own rules (consumers of last resort, else
 * counted as unhandled), in hold order; when a higher-ranked policy replaces it, the hold stays as it is.
 */
@ConsumerType
public interface UnhandledEventPolicy {

    /**
     * @param eventType the event's fully qualified type name
     * @param typeHierarchy the type name first, then its superclasses and all its interfaces (as the bus matches
     *        behaviours), excluding {@code java.lang.Object}; so it also names {@code BrainIoTEvent},
     *        {@code org.osgi.dto.DTO} and {@code java.lang.Cloneable}, which a policy will usually not search for;
     *        for an untyped event only its type name
     * @return what to do with this event
     */
    Disposition unhandled(String eventType, List<String> typeHierarchy);

    /**
     * As {@link #unhandled(String, List)}, with the event's fields at hand: a policy that chooses where to install
     * by what the event names (a robot, a door) reads them; the bus calls this one, and this default ignores the
     * fields. Since 1.3.
     *
     * @param fields builds a copy of the event's fields (nested data as maps and lists) when called: call it only
     *        when needed, on the calling thread, before returning
     */
    default Disposition unhandled(String eventType, List<String> typeHierarchy,
            Supplier<Map<String, Object>> fields) {
        return unhandled(eventType, typeHierarchy);
    }

    /**
     * @return how many events the bus may hold for this policy, all types together (at least 1; read each time an
     *         event is to be held, so it may change); when the hold is full a
     *         publisher of an event to be held waits as for a full behaviour queue (the bus's overflow timeout),
     *         then gets an {@code EventBusOverflowException}
     */
    int maxHeldEvents();

    /** What the bus does with one unhandled event. */
    enum Disposition {
        /**
         * Keep it, in publish order, until a behaviour that consumes it is registered with the bus: then it is
         * handed to that behaviour before any event published after that moment; or until {@link HeldEvents#discard}.
         */
        HOLD,
        /** Count it as unhandled (and log its type once); never held, the publisher never waits. */
        UNHANDLED,
        /** Give it to the consumers of last resort, if any; else count it as unhandled. */
        LAST_RESORT
    }
}
