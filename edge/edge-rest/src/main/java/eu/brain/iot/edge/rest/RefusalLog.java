package eu.brain.iot.edge.rest;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.LongSupplier;

import org.osgi.service.log.Logger;

/**
 * Logs a refused request (a body too slow, 408) in one short line, at most once per client address per period, so
 * that a client opening hundreds of such requests costs the log a line a minute, not a line each. The lines left
 * out are counted and said with the next one for that address.
 * <p>
 * Threads: any (the body deadline's timer, container threads); the map is guarded by {@code this}, the logger is
 * called outside it.
 */
final class RefusalLog {

    /** Addresses remembered at most: beyond, the oldest is forgotten (its next refusal is logged again). */
    static final int MAX_ADDRESSES = 1_024;

    private final Logger log;
    private final long periodNanos;
    private final LongSupplier clock;
    /** Guarded by {@code this}: per address, when it was last logged and how many refusals were not. */
    private final Map<String, long[]> last = new LinkedHashMap<>(16, 0.75f, true) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(Map.Entry<String, long[]> eldest) {
            return size() > MAX_ADDRESSES;
        }
    };

    RefusalLog(Logger log, long periodMillis, LongSupplier nanoClock) {
        this.log = log;
        this.periodNanos = periodMillis * 1_000_000;
        this.clock = nanoClock;
    }

    /** Logs {@code what} for {@code address} at warn unless that address was logged within the period. */
    void refused(String address, String what) {
        long now = clock.getAsLong();
        long skipped;
        synchronized (this) {
            long[] seen = last.get(address);
            if (seen != null && now - seen[0] < periodNanos) {
                seen[1]++;
                return;
            }
            skipped = seen == null ? 0 : seen[1];
            last.put(address, new long[] { now, 0 });
        }
        log.warn("client " + address + ": " + what + (skipped > 0 ? " (and " + skipped + " more since the last "
                + "such line)" : "") + "; at most one such line per address every " + periodNanos / 1_000_000_000
                + " s");
    }
}
