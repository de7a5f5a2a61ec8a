package eu.brain.iot.edge.rest;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.service.log.Logger;

/**
 * The policy that keeps room for ordinary requests: at most {@code max} event streams open at once, apart from the
 * connection limit of the whole server. A stream holds its connection for as long as the client wants, so without
 * this cap clients that only open streams (from one machine, where the per-client limit does not apply) could take
 * every connection the server accepts and lock out every other request. Past the cap a new stream is answered 503
 * at once. Reaching the cap is logged (warn) once until the count drops below it again (info).
 * <p>
 * Threads: container threads open streams, any thread closes them; the counts are atomics.
 */
final class StreamLimit {

    private final int max;
    private final String what;
    private final String setting;
    private final Logger log;
    private final AtomicInteger open = new AtomicInteger();
    private final AtomicBoolean full = new AtomicBoolean();

    /**
     * @param what the streams, for the log ("the edge's SSE streams (/sensinact/subscribe)")
     * @param setting the configuration that sets {@code max}, for the log and the answer
     */
    StreamLimit(int max, String what, String setting, Logger log) {
        this.max = max;
        this.what = what;
        this.setting = setting;
        this.log = log;
    }

    /** @return whether a stream may open; if so, {@link #release()} must follow exactly once when it closes */
    boolean tryAcquire() {
        while (true) {
            int n = open.get();
            if (n >= max) {
                if (full.compareAndSet(false, true)) {
                    log.warn(what + ": " + max + " streams open, the most allowed (" + setting + "); new ones are "
                            + "answered 503 until one closes, so that other requests keep their connections");
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
            log.info(what + ": below " + max + " streams again; new streams are accepted");
        }
    }

    int open() {
        return open.get();
    }

    /** The refusal's text for the client. */
    String refusal() {
        return "too many event streams are open on this node (" + max + ", " + setting + "); close one or try again "
                + "later";
    }
}
