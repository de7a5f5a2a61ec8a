package eu.brain.iot.edge.impl;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** Where the edge's events go: the event bus's {@code tryDeliver} in a framework, a list in a test. */
@FunctionalInterface
interface EventSink {

    /**
     * Offer an event without waiting.
     *
     * @return true when taken; false when there is no room now (the caller keeps the event: see {@link Outbox})
     */
    boolean offer(BrainIoTEvent event);
}
