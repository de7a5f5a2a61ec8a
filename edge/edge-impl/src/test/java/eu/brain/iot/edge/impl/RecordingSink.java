package eu.brain.iot.edge.impl;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Predicate;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** Keeps every event the edge publishes, for tests to look for. */
final class RecordingSink implements EventSink {

    final List<BrainIoTEvent> events = new CopyOnWriteArrayList<>();

    /** While false, every event is refused, as a bus whose behaviour queue is full refuses it. */
    volatile boolean accepting = true;
    /** Events refused so far. */
    final java.util.concurrent.atomic.AtomicLong refused = new java.util.concurrent.atomic.AtomicLong();

    @Override
    public boolean offer(BrainIoTEvent event) {
        if (!accepting) {
            refused.incrementAndGet();
            return false;
        }
        events.add(event);
        return true;
    }

    <E extends BrainIoTEvent> List<E> of(Class<E> type) {
        return events.stream().filter(type::isInstance).map(type::cast).toList();
    }

    <E extends BrainIoTEvent> List<E> of(Class<E> type, Predicate<E> test) {
        return of(type).stream().filter(test).toList();
    }
}
