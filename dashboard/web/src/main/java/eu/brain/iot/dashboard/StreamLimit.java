package eu.brain.iot.dashboard;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.service.log.Logger;

/**
 * The policy that keeps room for the node's other requests: at most {@code max.streams} dashboard streams open at
 * once. A stream holds its connection for as long as the page stays open, and every program on this machine connects
 * from the same address, so without this cap streams alone could take every connection the server accepts
 * ({@code max.connections} of the edge's REST configuration) and lock out the REST API and the page itself. Past the
 * cap a new stream is answered 503 at once; reaching it is logged (warn) once until the count drops below it (info).
 * <p>
 * Threads: container threads open streams, any thread closes them; the counts are atomics.
 */
final class StreamLimit {

    private final int max;
    private final Logger log;
    private final AtomicInteger open = new AtomicInteger();
    private final AtomicBoolean full = new AtomicBoolean();

    StreamLimit(int max, Logger log) {
        this.max = max;
        this.log = log;
    }

    /** @return whether a stream may open; if so, {@link #release()} must follow exactly once when it closes */
    boolean tryAcquire() {
        while (true) {
            int n = open.get();
            if (n >= max) {
                if (full.compareAndSet(false, true)) {
                    log.warn("dashboard: " + max + " streams open, the most allowed (max.streams of "
                            + DashboardConfig.PID + "); new ones are answered 503 until one closes, so that other "
                            + "requests keep their connections");
                }
                return false;
            }
            if (open.compareAndSet(n, n + 1)) {
                return true;
            }
        }
    }

    void release() {
        if (open.decrementAndGet() < max && full.compareAndSet(true, false)) {
            log.info("dashboard: below " + max + " streams again; new streams are accepted");
        }
    }

    String refusal() {
        return "too many dashboard streams are open on this node (" + max + ", max.streams of " + DashboardConfig.PID
                + "); close a dashboard page or try again later";
    }
}
