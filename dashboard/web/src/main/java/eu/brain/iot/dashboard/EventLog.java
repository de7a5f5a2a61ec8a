package eu.brain.iot.dashboard;

import java.util.ArrayDeque;
import java.util.List;
import java.util.Optional;

/**
 * The last events sent, for clients that reconnect with {@code Last-Event-ID}. An id is {@code <epoch>-<n>}: the
 * epoch changes whenever the dashboard starts (a node restart), so an id from before is recognised as foreign and
 * its client gets a fresh snapshot instead of a replay.
 * <p>
 * Thread: owned by the dashboard's thread ({@link Hub}).
 */
final class EventLog {

    /** One SSE event, ready to write. */
    record Frame(long n, String text) {
    }

    private final String epoch;
    private final int capacity;
    private final ArrayDeque<Frame> frames = new ArrayDeque<>();
    private long last;

    EventLog(String epoch, int capacity) {
        this.epoch = epoch;
        this.capacity = capacity;
    }

    /** The id of the last event sent (or of the start, before any). */
    String lastId() {
        return epoch + "-" + last;
    }

    /** Makes the next event, keeps it for replays and returns it. */
    Frame append(String type, String json) {
        long n = ++last;
        Frame f = new Frame(n, frame(epoch + "-" + n, type, json));
        frames.addLast(f);
        if (frames.size() > capacity) {
            frames.removeFirst();
        }
        return f;
    }

    /** A snapshot event carrying the current id, sent alone (never kept: it replaces the state, it is no change). */
    String snapshot(String json) {
        return frame(lastId(), "snapshot", json);
    }

    /**
     * The events after {@code lastEventId}, or empty when they cannot be replayed (another epoch, unknown or too
     * old an id): then the client needs a snapshot.
     */
    Optional<List<Frame>> after(String lastEventId) {
        if (lastEventId == null || !lastEventId.startsWith(epoch + "-")) {
            return Optional.empty();
        }
        long n;
        try {
            n = Long.parseLong(lastEventId.substring(epoch.length() + 1));
        } catch (NumberFormatException e) {
            return Optional.empty();
        }
        if (n > last) {
            return Optional.empty();
        }
        if (n == last) {
            return Optional.of(List.of());
        }
        Frame first = frames.peekFirst();
        if (first == null || first.n() > n + 1) {
            return Optional.empty(); // some of the missed events are gone
        }
        return Optional.of(frames.stream().filter(f -> f.n() > n).toList());
    }

    private static String frame(String id, String type, String json) {
        return "id: " + id + "\nevent: " + type + "\ndata: " + json + "\n\n";
    }
}
