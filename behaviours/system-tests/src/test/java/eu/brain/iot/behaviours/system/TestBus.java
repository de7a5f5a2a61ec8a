package eu.brain.iot.behaviours.system;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * A single-threaded, in-order stand-in for the event bus, so the generated behaviours can be driven
 * deterministically without an OSGi framework: published events queue up; {@link #drain()} hands each one, in
 * publish order, to every behaviour (behaviours ignore what they do not consume). Records everything published.
 * Owned by the test thread.
 */
final class TestBus implements EventBus {

    private final Deque<BrainIoTEvent> queue = new ArrayDeque<>();
    private final List<SmartBehaviour<BrainIoTEvent>> behaviours = new ArrayList<>();
    private final List<BrainIoTEvent> published = new ArrayList<>();

    void register(SmartBehaviour<BrainIoTEvent> behaviour) {
        behaviours.add(behaviour);
    }

    @Override
    public void deliver(BrainIoTEvent event) {
        published.add(event);
        queue.add(event);
    }

    @Override
    public void deliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("the generated behaviours publish typed events");
    }

    @Override
    public boolean tryDeliver(BrainIoTEvent event) {
        deliver(event); // its queue has no bound: there is always room
        return true;
    }

    @Override
    public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("the generated behaviours publish typed events");
    }

    /** Publishes an event as the environment would, then delivers until nothing is left. */
    void publish(BrainIoTEvent event) {
        deliver(event);
        drain();
    }

    void drain() {
        int guard = 0;
        while (!queue.isEmpty()) {
            if (++guard > 10_000) {
                throw new AssertionError("the behaviours keep publishing: " + published.subList(
                        Math.max(0, published.size() - 10), published.size()));
            }
            BrainIoTEvent event = queue.poll();
            for (SmartBehaviour<BrainIoTEvent> b : behaviours) {
                b.notify(event);
            }
        }
    }

    <T extends BrainIoTEvent> List<T> published(Class<T> type) {
        return published.stream().filter(type::isInstance).map(type::cast).toList();
    }
}
