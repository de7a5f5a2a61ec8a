package eu.brain.iot.edge.impl;

import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * The edge's one fleet thread, which owns the polling schedule, the {@link DeviceStore}'s writes, the
 * {@link MissionTracker} and the {@link Outbox}: work from other threads (answers, history, command outcomes)
 * is handed to it here.
 */
final class FleetThread implements Executor {

    private final ScheduledExecutorService executor;

    /** @param nodeName the node's name, in the thread's ({@code edge-fleet-<node>}: several edges in one JVM apart) */
    FleetThread(String nodeName) {
        executor = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, "edge-fleet-" + nodeName);
            t.setDaemon(true);
            return t;
        });
    }

    @Override
    public void execute(Runnable task) {
        executor.execute(task);
    }

    /** Run a task on the fleet thread; once the edge stopped, say what was not done ({@code what}). */
    void run(Runnable task, String what, EdgeLog log) {
        try {
            executor.execute(task);
        } catch (RejectedExecutionException stopped) {
            log.warn("the edge is stopping: " + what + " not done");
        }
    }

    ScheduledFuture<?> schedule(Runnable task, long delay, TimeUnit unit) {
        return executor.schedule(task, delay, unit);
    }

    /**
     * Stops the fleet thread and waits (up to 2 s) for the task it is running, so that the edge's HTTP client,
     * closed next, is not used by a poll still under way (Netty would log an ERROR with a stack trace).
     */
    void shutdown() {
        executor.shutdownNow();
        try {
            executor.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
