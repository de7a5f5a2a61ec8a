package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.view.CommandCounts;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

/**
 * Counts the commands the fleet answered, by outcome. Thread-safe: I/O threads and the world thread record
 * answers, any thread takes a {@link #snapshot()} (the counts of one snapshot may be a few answers apart).
 */
public final class CommandCounter {
    private final LongAdder accepted = new LongAdder();
    private final Map<Integer, LongAdder> refused = new ConcurrentHashMap<>();

    /** @param status the HTTP status of the answer, 0 when the connection was dropped without one */
    void record(int status) {
        if (status >= 200 && status < 300) {
            accepted.increment();
        } else {
            refused.computeIfAbsent(status, s -> new LongAdder()).increment();
        }
    }

    public CommandCounts snapshot() {
        long ok = accepted.sum();
        Map<String, Long> byStatus = new TreeMap<>();
        long no = 0;
        for (Map.Entry<Integer, LongAdder> e : refused.entrySet()) {
            long n = e.getValue().sum();
            byStatus.put(String.valueOf(e.getKey()), n);
            no += n;
        }
        return new CommandCounts(ok + no, ok, no, Map.copyOf(byStatus));
    }
}
