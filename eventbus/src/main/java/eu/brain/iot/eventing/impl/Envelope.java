package eu.brain.iot.eventing.impl;

import java.util.List;

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
    /** The type name, then its supertypes and interfaces as routed; {@code null} when only the name is known. */
    final List<String> typeNames;
    /** Told when each consumer is done with the envelope; {@code null} for local events. */
    final Completion completion;
    /**
     * Whether its publisher waits for room ({@code deliver}) rather than giving up at once ({@code tryDeliver}):
     * how it is published again if it meets a forwarder that left (see {@link Orphans}).
     */
    final boolean publisherWaits;
    /** The consumers it was queued for: one that leaves without taking it hands it to none of the others. */
    final ConsumerChannel[] reached;

    Envelope(Object payload, EventTypeCounters counters, boolean exclusive) {
        this(payload, counters, exclusive, null, null, false, new ConsumerChannel[0]);
    }

    Envelope(Object payload, EventTypeCounters counters, boolean exclusive, List<String> typeNames,
            Completion completion, boolean publisherWaits, ConsumerChannel[] reached) {
        this.payload = payload;
        this.counters = counters;
        this.exclusive = exclusive;
        this.typeNames = typeNames;
        this.completion = completion;
        this.publisherWaits = publisherWaits;
        this.reached = reached;
    }

    /** One consumer is done with this envelope (called it, or discarded it). */
    void consumed() {
        if (completion != null) {
            completion.countDown();
        }
    }

    String type() {
        return counters.eventType;
    }
}
