package eu.brain.iot.bms.impl;

import java.util.concurrent.Executor;

/**
 * The BMS's own thread and its clock. Every state change after an episode's start runs as a task here, one at a time,
 * so the BMS's bookkeeping (install jobs, retries) needs no lock. Tests use a manual implementation with virtual
 * time: retries, deadlines and the negative cache are tested without sleeping.
 */
interface Scheduler extends Executor {

    /** Run {@code task} on the BMS's thread after {@code delayMillis}. */
    void schedule(Runnable task, long delayMillis);

    /** Run {@code task} on the BMS's thread every {@code periodMillis}, until closed. */
    void every(long periodMillis, Runnable task);

    /** @return the time, milliseconds since the epoch */
    long now();

    /** Stop: queued and scheduled tasks are dropped. */
    void close();
}
