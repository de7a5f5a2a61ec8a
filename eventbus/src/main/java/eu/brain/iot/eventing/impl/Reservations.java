package eu.brain.iot.eventing.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * Room for one event in the queues of all its consumers, all or none. Runs on the publisher's thread and keeps no
 * state: the queues' own counters are what publishers share (see {@link ConsumerChannel}).
 */
final class Reservations {

    private Reservations() {
    }

    /**
     * Reserve a queue slot in every target, or none: waits for room up to the overflow timeout if {@code wait}.
     * A target that is stalled (its queue full and its notify() not returned for the overflow timeout, see
     * {@link StallPolicy}) is skipped and the event counted as discarded for it.
     *
     * @return the targets with a slot ({@code targets} itself when none was skipped), or null when a queue was
     *         full and {@code wait} is false (nothing reserved then)
     */
    static ConsumerChannel[] reserveAll(ConsumerChannel[] targets, EventTypeCounters typeCounters, boolean wait,
            long overflowTimeoutNanos, int queueCapacity) {
        long deadline = 0;
        boolean[] skip = null;
        for (int i = 0; i < targets.length; i++) {
            ConsumerChannel target = targets[i];
            while (!target.tryReserve()) {
                if (target.isClosed()) {
                    break; // it is leaving: a behaviour's envelope is discarded, a forwarder's published again (Orphans)
                }
                long now = System.nanoTime();
                if (target.stalledWhenFull(now, overflowTimeoutNanos)) {
                    if (skip == null) {
                        skip = new boolean[targets.length];
                    }
                    skip[i] = true;
                    break;
                }
                if (deadline == 0) {
                    deadline = now + overflowTimeoutNanos;
                }
                if (!wait || now - deadline >= 0) {
                    for (int j = 0; j < i; j++) {
                        if (skip == null || !skip[j]) {
                            targets[j].release();
                        }
                    }
                    if (!wait) {
                        return null;
                    }
                    throw Overflows.queueFull(typeCounters.eventType, target.spec, queueCapacity,
                            TimeUnit.NANOSECONDS.toMillis(overflowTimeoutNanos));
                }
                LockSupport.parkNanos(50_000);
            }
        }
        return skip == null ? targets : withoutSkipped(targets, skip, typeCounters);
    }

    private static ConsumerChannel[] withoutSkipped(ConsumerChannel[] targets, boolean[] skip,
            EventTypeCounters typeCounters) {
        List<ConsumerChannel> kept = new ArrayList<>(targets.length);
        for (int i = 0; i < targets.length; i++) {
            if (skip[i]) {
                targets[i].skipped(typeCounters);
            } else {
                kept.add(targets[i]);
            }
        }
        return kept.toArray(new ConsumerChannel[0]);
    }
}
