package eu.brain.iot.eventing.impl;

import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.service.log.Logger;

/**
 * Runs an action once every consumer of an event from another node is done with it: the end-to-end acknowledgement
 * of the fabric waits for it. Counted down by the delivery workers of the consumers (any thread); the action runs on
 * the thread of the last one, once.
 */
final class Completion {

    private final AtomicInteger left;
    private final Runnable done;
    private final Logger log;

    Completion(int consumers, Runnable done, Logger log) {
        this.left = new AtomicInteger(consumers);
        this.done = done;
        this.log = log;
    }

    void countDown() {
        if (left.decrementAndGet() == 0) {
            run(done, log);
        }
    }

    /** Run an action if there is one ({@code null} for a local event), never letting its failure escape. */
    static void run(Runnable action, Logger log) {
        if (action == null) {
            return;
        }
        try {
            action.run();
        } catch (RuntimeException e) {
            log.error("The completion action of an event from another node failed; its acknowledgement may be late",
                    e);
        }
    }
}
