package eu.brain.iot.eventing.impl;

/**
 * One accepted event on its way to one or more consumers. Immutable once queued: the payload is the bus's own
 * snapshot (a {@link eu.brain.iot.eventing.api.BrainIoTEvent} or a {@code Map} for untyped events) and is only
 * read by delivery threads, which each make their consumer's own copy from it, unless the envelope is
 * {@link #exclusive}: then its single consumer receives the snapshot itself.
 */
final class Envelope {
    final Object payload;
    final EventTypeCounters counters;
    final boolean exclusive;

    Envelope(Object payload, EventTypeCounters counters, boolean exclusive) {
        this.payload = payload;
        this.counters = counters;
        this.exclusive = exclusive;
    }

    String type() {
        return counters.eventType;
    }
}
