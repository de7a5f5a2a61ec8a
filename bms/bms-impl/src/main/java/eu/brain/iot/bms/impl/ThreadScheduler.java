package eu.brain.iot.bms.impl;

import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

import org.osgi.service.log.Logger;

/**
 * The real {@link Scheduler}: one daemon thread named {@code brain-iot-bms}. A task that throws is logged and the
 * thread goes on. Tasks submitted after {@link #close()} are ignored (an install's answer arriving while the BMS
 * stops).
 */
final class ThreadScheduler implements Scheduler {

    private final ScheduledThreadPoolExecutor executor;
    private final Logger log;

    ThreadScheduler(String name, Logger log) {
        this.log = log;
        this.executor = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        });
        executor.setRemoveOnCancelPolicy(true);
        executor.setExecuteExistingDelayedTasksAfterShutdownPolicy(false);
    }

    @Override
    public void execute(Runnable task) {
        schedule(task, 0);
    }

    @Override
    public void schedule(Runnable task, long delayMillis) {
        try {
            executor.schedule(guarded(task), Math.max(0, delayMillis), TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException closed) {
            // stopping: nothing more to do
        }
    }

    @Override
    public void every(long periodMillis, Runnable task) {
        try {
            executor.scheduleWithFixedDelay(guarded(task), periodMillis, periodMillis, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException closed) {
            // stopping
        }
    }

    private Runnable guarded(Runnable task) {
        return () -> {
            try {
                task.run();
            } catch (RuntimeException | Error e) {
                log.error("Behaviour Management Service: an internal task failed; the BMS goes on", e);
            }
        };
    }

    @Override
    public long now() {
        return System.currentTimeMillis();
    }

    @Override
    public void close() {
        executor.shutdownNow();
    }
}
