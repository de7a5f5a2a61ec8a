package eu.brain.iot.bms.impl;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import eu.brain.iot.eventing.spi.HeldEvents;
import eu.brain.iot.eventing.spi.HeldType;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * The bus's side of the SPI as the BMS core sees it, for unit tests: {@link #publish} asks the policy and keeps
 * the counts of held and unhandled events; {@link #register} hands a type's held events to a behaviour. The real
 * bus's hold (order, exactly once) is tested with the real bus in eventbus/ and itests/.
 */
final class FakeHold implements HeldEvents {

    private final Map<String, HeldType> held = new LinkedHashMap<>();
    final List<String> discards = new CopyOnWriteArrayList<>();
    long unhandled;
    long lastResort;
    long handedOver;

    synchronized Disposition publish(BehaviourManager bms, String type, String... supertypes) {
        List<String> hierarchy = new ArrayList<>();
        hierarchy.add(type);
        hierarchy.addAll(List.of(supertypes));
        Disposition d = bms.unhandled(type, hierarchy, Map::of);
        switch (d) {
        case HOLD -> held.computeIfAbsent(type, t -> {
            HeldType h = new HeldType();
            h.eventType = t;
            h.since = 1;
            return h;
        }).count++;
        case UNHANDLED, LAST_RESORT -> unhandled++; // no consumer of last resort here: counted as unhandled
        }
        return d;
    }

    synchronized int count(String type) {
        HeldType h = held.get(type);
        return h == null ? 0 : h.count;
    }

    /** A behaviour taking {@code type} is registered: its held events go to it. */
    synchronized void register(String type) {
        HeldType h = held.remove(type);
        handedOver += h == null ? 0 : h.count;
    }

    @Override
    public synchronized List<HeldType> held() {
        return new ArrayList<>(held.values());
    }

    @Override
    public synchronized int discard(String eventType, String reason) {
        HeldType h = held.remove(eventType);
        discards.add(eventType + ": " + reason);
        return h == null ? 0 : h.count;
    }
}
