package eu.brain.iot.bms.impl;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;

/** Keeps the alerts the BMS publishes. */
final class RecordingBus implements EventBus {

    final List<BrainIoTEvent> alerts = new CopyOnWriteArrayList<>();

    @Override
    public void deliver(BrainIoTEvent event) {
        alerts.add(event);
    }

    @Override
    public void deliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("the BMS publishes typed alerts");
    }

    @Override
    public boolean tryDeliver(BrainIoTEvent event) {
        deliver(event);
        return true;
    }

    @Override
    public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("the BMS publishes typed alerts");
    }

    <T extends BrainIoTEvent> List<T> of(Class<T> type) {
        return alerts.stream().filter(type::isInstance).map(type::cast).toList();
    }
}
