package eu.brain.iot.eventing.impl;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;

import org.osgi.service.log.Logger;

/**
 * The policy for a behaviour that is stalled, not merely slow: when its queue is full and its {@code notify()} has
 * not returned (no event taken off its queue) for the overflow timeout, it stops taking events. Publishers then
 * skip it, and what they would have queued for it is counted as discarded, so that the other consumers of the
 * same types keep receiving. A behaviour that is merely slow takes events while its queue is full, so publishers
 * keep waiting for it (back-pressure) as for any full queue. The behaviour takes events again as soon as its
 * {@code notify()} returns; its queued events were kept and are delivered.
 * <p>
 * Ownership: one per {@link ConsumerChannel}. Publishers that find the queue full call {@link #skip} under this
 * object's lock (only then: never on the hot path of a queue with room). The channel's delivery worker reads
 * {@link #stalled} after each call and, once set, calls {@link #resumed} (same lock). {@link #discarded} is an
 * adder updated by publishers and read by statistics.
 */
final class StallPolicy {

    private final ConsumerSpec spec;
    private final Logger log;
    /** The channel's taken count when the queue was first seen full without progress; -1: not seen yet. */
    private long fullAtTaken = -1;
    /** When the queue was first seen full at {@link #fullAtTaken} (System.nanoTime). */
    private long fullSince;
    /** Set while the behaviour is stalled; read without the lock by its worker after each call. */
    private volatile boolean stalled;
    /** Events skipped in the current stall, for the log line when it ends. */
    private long skippedThisStall;
    private final LongAdder discarded = new LongAdder();

    StallPolicy(ConsumerSpec spec, Logger log) {
        this.spec = spec;
        this.log = log;
    }

    /**
     * A publisher found the queue full: whether to skip this behaviour (it is stalled) rather than wait for room.
     *
     * @param taken the channel's count of events taken off its queue, which moves whenever notify() returns
     */
    synchronized boolean skip(long taken, long now, long timeoutNanos, int capacity) {
        if (taken != fullAtTaken) {
            // Progress since the last look (or the first look): a slow behaviour, not a stalled one.
            if (stalled) {
                endStall();
            }
            fullAtTaken = taken;
            fullSince = now;
            return false;
        }
        if (!stalled && now - fullSince >= timeoutNanos) {
            stalled = true;
            skippedThisStall = 0;
            log.error("Smart behaviour {} (bundle {}) is stalled: its queue is full ({} events) and its notify() "
                    + "has not returned for {} ms (overflow.timeout.ms). It takes no more events until notify() "
                    + "returns; events for it are discarded (counted as 'discarded', Gogo: bus:behaviours shows it "
                    + "as stalled) so that the other behaviours of the same event types keep receiving theirs.",
                    spec.name(), spec.bundle(), capacity, TimeUnit.NANOSECONDS.toMillis(now - fullSince));
        }
        return stalled;
    }

    /** Count an event that was not queued for this behaviour because it is stalled. */
    void skipped(EventTypeCounters counters) {
        counters.discarded.increment();
        discarded.increment();
        synchronized (this) {
            skippedThisStall++;
        }
    }

    /** Whether the behaviour is stalled; the delivery worker looks after each call (one volatile read). */
    boolean isStalled() {
        return stalled;
    }

    /** Its notify() returned: it takes events again. */
    synchronized void resumed() {
        if (stalled) {
            endStall();
            fullAtTaken = -1;
        }
    }

    private void endStall() {
        stalled = false;
        log.warn("Smart behaviour {} (bundle {}) returned from notify() and takes events again; {} events were "
                + "discarded for it while it was stalled.", spec.name(), spec.bundle(), skippedThisStall);
    }

    long discarded() {
        return discarded.sum();
    }
}
