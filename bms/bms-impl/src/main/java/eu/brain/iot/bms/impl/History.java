package eu.brain.iot.bms.impl;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bms.monitoring.api.HistoryEntry;

/**
 * The last {@code history.size} things the BMS did, for {@code bms:history}. Written by the BMS's thread, read by
 * any (Gogo): guarded by {@code this}.
 */
final class History {

    private final ArrayDeque<HistoryEntry> entries = new ArrayDeque<>();
    private int capacity;

    History(int capacity) {
        this.capacity = capacity;
    }

    synchronized void resize(int newCapacity) {
        capacity = newCapacity;
        trim();
    }

    synchronized void add(HistoryEntry entry) {
        entries.addLast(entry);
        trim();
    }

    private void trim() {
        while (entries.size() > capacity) {
            entries.removeFirst();
        }
    }

    synchronized List<HistoryEntry> entries() {
        return new ArrayList<>(entries);
    }

    static HistoryEntry entry(long time, String kind, List<String> types, String behaviour, long durationMs,
            int attempt, int held, String reason) {
        HistoryEntry e = new HistoryEntry();
        e.time = time;
        e.kind = kind;
        e.eventTypes = List.copyOf(types);
        e.behaviour = behaviour;
        e.durationMs = durationMs;
        e.attempt = attempt;
        e.heldEvents = held;
        e.reason = reason;
        return e;
    }
}
