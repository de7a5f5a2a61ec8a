package eu.brain.iot.eventing.impl;

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
     *
     * @return false when a queue was full and {@code wait} is false (nothing reserved then)
     */
    static boolean reserveAll(ConsumerChannel[] targets, String eventType, boolean wait, long overflowTimeoutNanos,
            int queueCapacity) {
        long deadline = 0;
        for (int i = 0; i < targets.length; i++) {
            ConsumerChannel target = targets[i];
            while (!target.tryReserve()) {
                if (target.isClosed()) {
                    break; // it is leaving; the envelope will be counted as discarded
                }
                long now = System.nanoTime();
                if (deadline == 0) {
                    deadline = now + overflowTimeoutNanos;
                }
                if (!wait || now - deadline >= 0) {
                    for (int j = 0; j < i; j++) {
                        targets[j].release();
                    }
                    if (!wait) {
                        return false;
                    }
                    throw Overflows.queueFull(eventType, target.spec, queueCapacity,
                            TimeUnit.NANOSECONDS.toMillis(overflowTimeoutNanos));
                }
                LockSupport.parkNanos(50_000);
            }
        }
        return true;
    }

}
