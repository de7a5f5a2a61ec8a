package eu.brain.iot.bms.impl;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;

/**
 * What the BMS searched for each event type that has a state: the type's hierarchy (what the repositories are asked
 * for) and the fields of the first event of its episode (an installer spanning several nodes prefers the node that
 * owns the device it names). Added by publishers when an episode starts, dropped with the type's state.
 * <p>
 * Thread-safe: one concurrent map of immutable entries.
 */
final class SearchedTypes {

    private record Searched(List<String> hierarchy, Map<String, Object> firstEvent) {
    }

    private final ConcurrentHashMap<String, Searched> types = new ConcurrentHashMap<>();

    /** An episode starts: keeps the hierarchy and the event's fields (built only if none are kept yet). */
    void started(String eventType, List<String> hierarchy, Supplier<Map<String, Object>> fields) {
        types.computeIfAbsent(eventType, t -> new Searched(hierarchy, Collections.unmodifiableMap(fields.get())));
    }

    /** @return the hierarchy searched for the type, or the type alone */
    List<String> hierarchy(String eventType) {
        Searched s = types.get(eventType);
        return s == null ? List.of(eventType) : s.hierarchy();
    }

    /** @return the fields of the episode's first event, or none */
    Map<String, Object> firstEvent(String eventType) {
        Searched s = types.get(eventType);
        return s == null ? Map.of() : s.firstEvent();
    }

    void forget(String eventType) {
        types.remove(eventType);
    }
}
