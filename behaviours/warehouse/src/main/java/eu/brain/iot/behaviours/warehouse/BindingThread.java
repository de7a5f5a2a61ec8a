package eu.brain.iot.behaviours.warehouse;

import java.util.concurrent.Future;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * The one thread of a behaviour's binding to the edge, which owns the binding's state: it takes the events handed
 * to it and looks at the fleet once per poll of the warehouse, whatever the fleet's speed factor.
 */
public final class BindingThread implements AutoCloseable {

    private final ScheduledExecutorService executor;
    private final long periodNanos;

    /**
     * @param name         the thread's name
     * @param speed        the fleet's speed factor (warehouse time runs this many times faster than wall time)
     * @param pollMillis   warehouse time between two looks
     */
    public BindingThread(String name, double speed, long pollMillis) {
        double s = speed > 0 ? speed : 1;
        this.periodNanos = Math.max(TimeUnit.MILLISECONDS.toNanos(5), (long) (TimeUnit.MILLISECONDS.toNanos(pollMillis)
                / s));
        this.executor = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Starts the looks, once the binding is fully built: {@code look} runs on this thread once per period until the
     * returned future is cancelled (or the thread closed).
     */
    public Future<?> start(Runnable look) {
        return executor.scheduleWithFixedDelay(look, periodNanos, periodNanos, TimeUnit.NANOSECONDS);
    }

    /** @return the wall time between two looks, in nanoseconds */
    public long periodNanos() {
        return periodNanos;
    }

    /** Runs a task on this thread. */
    public void execute(Runnable task) {
        executor.execute(task);
    }

    @Override
    public void close() {
        executor.shutdownNow();
    }
}
