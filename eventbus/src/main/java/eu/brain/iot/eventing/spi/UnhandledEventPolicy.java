package eu.brain.iot.eventing.spi;

import java.util.List;

import org.osgi.annotation.versioning.ConsumerType;

/**
 * Decides what the bus does with an event that no behaviour consumes (after filters). Registered as an OSGi
 * service by a Behaviour Management Service; the bus follows the highest-ranked one. Without any policy the bus
 * behaves as before: consumers of last resort, else counted as unhandled.
 * <p>
 * Threading: {@link #unhandled} is called on the publisher's thread, for every such event, while the bus may
 * hold an internal lock: it must answer at once (a map look-up), must not block, must not do I/O and must not
 * publish on the bus. Work such as searching a repository belongs on the policy's own threads.
 */
@ConsumerType
public interface UnhandledEventPolicy {

    /**
     * @param eventType the event's fully qualified type name
     * @param typeHierarchy the type name first, then its superclasses and all its interfaces (as the bus matches
     *        behaviours), excluding {@code java.lang.Object}; for an untyped event only its type name
     * @return what to do with this event
     */
    Disposition unhandled(String eventType, List<String> typeHierarchy);

    /**
     * @return how many events the bus may hold for this policy, all types together; when the hold is full a
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
