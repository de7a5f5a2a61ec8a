package eu.brain.iot.eventing.integration;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;

/** A behaviour that keeps what it receives, typed or untyped. Its lists are thread-safe. */
public class Recorder implements SmartBehaviour<BrainIoTEvent>, UntypedSmartBehaviour {
    public final List<BrainIoTEvent> events = new CopyOnWriteArrayList<>();
    public final List<String> types = new CopyOnWriteArrayList<>();
    public final List<Map<String, Object>> maps = new CopyOnWriteArrayList<>();
    public final List<Thread> threads = new CopyOnWriteArrayList<>();

    @Override
    public void notify(BrainIoTEvent event) {
        threads.add(Thread.currentThread());
        events.add(event);
    }

    @Override
    public void notify(String eventType, Map<String, ?> properties) {
        types.add(eventType);
        @SuppressWarnings("unchecked")
        Map<String, Object> map = (Map<String, Object>) properties;
        maps.add(map);
    }
}
