package eu.brain.iot.edge.impl;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Predicate;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** Keeps every event the edge publishes, for tests to look for. */
final class RecordingSink implements EventSink {

    final List<BrainIoTEvent> events = new CopyOnWriteArrayList<>();

    @Override
    public void publish(BrainIoTEvent event) {
        events.add(event);
    }

    <E extends BrainIoTEvent> List<E> of(Class<E> type) {
        return events.stream().filter(type::isInstance).map(type::cast).toList();
    }

    <E extends BrainIoTEvent> List<E> of(Class<E> type, Predicate<E> test) {
        return of(type).stream().filter(test).toList();
    }
}
