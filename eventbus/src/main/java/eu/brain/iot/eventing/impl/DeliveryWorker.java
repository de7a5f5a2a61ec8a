package eu.brain.iot.eventing.impl;

/**
 * One delivery thread of the {@link DeliveryPool}: takes a ready behaviour from the run queue, runs its turn,
 * and so on until the pool lets it go.
 * <p>
 * Ownership: {@link #current} and {@link #turns} are written by this worker only and read by the
 * {@link StallWatchdog}; {@link #watch} belongs to the watchdog alone (kept in its own object so that the
 * watchdog's writes do not share a cache line with the worker's).
 */
final class DeliveryWorker implements Runnable {

    static final String NAME_PREFIX = "brain-iot-bus-worker-";

    final Thread thread;
    /** The watchdog's notes about this worker. */
    final StallWatchdog.Watch watch = new StallWatchdog.Watch();

    private final DeliveryPool pool;
    private final StallWatchdog watchdog;
    private final String name;
    /** The behaviour whose turn is running, {@code null} between turns. */
    private volatile ConsumerChannel current;
    /**
     * Turns begun. Written before {@link #current}, so a reader of {@code current} sees at least that turn's
     * number; an int, because reads of a plain int are never torn.
     */
    private int turns;

    DeliveryWorker(DeliveryPool pool, StallWatchdog watchdog, int number) {
        this.pool = pool;
        this.watchdog = watchdog;
        this.name = NAME_PREFIX + number;
        this.thread = new Thread(this, name);
        this.thread.setDaemon(true);
    }

    @Override
    public void run() {
        boolean expected = false;
        try {
            ConsumerChannel channel;
            while ((channel = pool.take(this)) != null) {
                turns++;
                current = channel;
                watchdog.workerBusy();
                try {
                    channel.runTurn();
                } finally {
                    current = null;
                }
            }
            expected = true;
        } finally {
            pool.exited(this, expected);
        }
    }

    ConsumerChannel current() {
        return current;
    }

    int turns() {
        return turns;
    }

    /** The thread's own name, without the stalled behaviour the watchdog may have added to it. */
    String name() {
        return name;
    }
}
