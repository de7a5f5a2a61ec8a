package eu.brain.iot.eventing.impl;

import eu.brain.iot.eventing.api.EventBusOverflowException;

/**
 * The errors of {@code EventBus.deliver} when it waited in vain for room: each says what was full, for how long,
 * and what to do. Stateless.
 */
final class Overflows {

    /** How an overflow of the hold names the "consumer" whose queue was full. */
    static final String HOLD_NAME = "the bus's hold of unhandled events";

    private Overflows() {
    }

    static EventBusOverflowException queueFull(String eventType, ConsumerSpec consumer, int capacity,
            long waitedMillis) {
        return new EventBusOverflowException(eventType, consumer.name(), "Event of type " + eventType
                + " not delivered: the queue of smart behaviour " + consumer.name() + " (bundle " + consumer.bundle()
                + ") stayed full (" + capacity + " events) for " + waitedMillis + " ms. That behaviour takes events, "
                + "but more slowly than they come; publish more slowly (or with tryDeliver, which never waits), fix it, or raise "
                + "queue.capacity in configuration PID " + BusConfig.PID + ".");
    }

    static EventBusOverflowException holdFull(String eventType, int max, String policy, long waitedMillis) {
        return new EventBusOverflowException(eventType, HOLD_NAME, "Event of type " + eventType
                + " not delivered: the bus already holds " + max + " events (the maximum of the unhandled-event "
                + "policy " + policy + ") waiting for behaviours to be installed, and none left the hold for "
                + waitedMillis + " ms. Publish more slowly, raise the policy's maximum of held events "
                + "(max.held.events of the Behaviour Management Service), or find out why no behaviour that "
                + "consumes the held types gets installed (Gogo: bus:stats, bms:pending).");
    }

    static EventBusOverflowException interrupted(String eventType) {
        return new EventBusOverflowException(eventType, HOLD_NAME, "Event of type " + eventType + " not delivered: "
                + "the publishing thread was interrupted while it waited for room in the bus's hold of unhandled "
                + "events.");
    }
}
