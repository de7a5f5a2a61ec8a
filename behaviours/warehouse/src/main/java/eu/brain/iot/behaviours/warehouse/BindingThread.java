package eu.brain.iot.behaviours.warehouse;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Future;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * The one thread of a behaviour's binding to the edge, which owns the binding's state: it takes the events handed
 * to it and looks at the fleet once per poll of the warehouse, whatever the fleet's speed factor.
 */
public final class BindingThread implements AutoCloseable {

    private static final System.Logger LOG = System.getLogger(BindingThread.class.getName());

    private final String name;
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
        this.name = name;
        this.executor = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Starts the looks, once the binding is fully built: {@code look} runs on this thread once per period of wall
     * time, from the start of one look to the start of the next (a fixed delay after each look would add the look's
     * own time to every period, and the looks would fall behind the polls), until the returned future is cancelled
     * (or the thread closed). A look that overruns its period is followed at once by the next, never by a burst of
     * the looks it missed; a look that throws is followed by the next all the same.
     */
    public Future<?> start(Runnable look) {
        CompletableFuture<Void> looks = new CompletableFuture<>();
        schedule(looks, look, periodNanos);
        return looks;
    }

    private void schedule(CompletableFuture<Void> looks, Runnable look, long delayNanos) {
        if (looks.isDone()) {
            return;
        }
        try {
            executor.schedule(() -> {
                if (looks.isDone()) {
                    return;
                }
                long start = System.nanoTime();
                try {
                    look.run();
                } catch (RuntimeException e) {
                    LOG.log(System.Logger.Level.WARNING, "a look of " + name + " failed; the next one comes all the"
                            + " same", e);
                } finally {
                    schedule(looks, look, Math.max(0, start + periodNanos - System.nanoTime()));
                }
            }, delayNanos, TimeUnit.NANOSECONDS);
        } catch (RejectedExecutionException e) {
            looks.cancel(false); // the thread is closed: no more looks
        }
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
