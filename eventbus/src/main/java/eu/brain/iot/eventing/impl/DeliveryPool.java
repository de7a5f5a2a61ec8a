package eu.brain.iot.eventing.impl;

import java.util.List;
import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

import org.osgi.service.log.Logger;

/**
 * The delivery workers that serve the behaviours' queues, and their run queue of ready behaviours.
 * <p>
 * Why a pool: one thread per behaviour meant that a single event published to 8 behaviours woke 8 sleeping
 * threads on 2 cores, and latency was the tail of that scheduling. Here as many workers as cores take turns on
 * the ready behaviours ({@link ConsumerChannel#runTurn}); a publisher wakes at most one worker per event, and a
 * worker that finds more ready behaviours wakes the next one, so the wake-ups are paid by the workers.
 * <p>
 * Isolation: a behaviour that blocks holds one worker. The {@link StallWatchdog} counts workers stuck in one
 * {@code notify()} call as stalled and {@link #ensureWorkers() adds workers} so that the pool always has its
 * configured number of workers that are not stalled. There is deliberately no upper bound: a behaviour holds at
 * most one worker at a time (its turn token), so the pool never grows beyond the configured size plus the
 * number of blocked behaviours. Workers beyond that size retire after being idle for {@code keepAliveNanos}.
 * <p>
 * Ownership: {@link #ready}, {@link #parked}, {@link #spinning} and {@link #workerCount} are shared by publishers
 * and workers and only changed atomically; {@link #workers} is changed when a worker starts or ends;
 * {@link #stalled} is written by the watchdog only. Wake-ups cannot be lost: a publisher queues, then looks for
 * a spinning or parked worker; a worker about to park registers as parked, then looks at the run queue again.
 */
final class DeliveryPool {

    /**
     * @param workers workers that are not stalled, at least 1
     * @param idleSpinNanos how long an idle worker yields its core before it parks
     * @param stallThresholdNanos how long one {@code notify()} may run before its worker counts as stalled
     * @param keepAliveNanos how long a worker beyond the configured number stays idle before it retires
     * @param stallWarningNanos how long one {@code notify()} may run before the stall is logged as a warning
     */
    record Settings(int workers, long idleSpinNanos, long stallThresholdNanos, long keepAliveNanos,
            long stallWarningNanos) {
        Settings {
            if (workers < 1 || stallThresholdNanos <= 0 || keepAliveNanos <= 0 || stallWarningNanos <= 0) {
                throw new IllegalArgumentException("invalid delivery settings " + workers + " workers, stall "
                        + "threshold " + stallThresholdNanos + " ns, keep-alive " + keepAliveNanos + " ns, stall "
                        + "warning " + stallWarningNanos + " ns");
            }
            idleSpinNanos = Math.max(0, idleSpinNanos);
        }

        /** With the default stall warning ({@link BusConfig#stall_warning_ms()}). */
        Settings(int workers, long idleSpinNanos, long stallThresholdNanos, long keepAliveNanos) {
            this(workers, idleSpinNanos, stallThresholdNanos, keepAliveNanos,
                    java.util.concurrent.TimeUnit.MILLISECONDS.toNanos(BusConfig.DEFAULT_STALL_WARNING_MS));
        }
    }

    /** Busy-wait polls before an idle worker starts yielding: events often come back to back. */
    private static final int SPINS = 64;

    /** Replaced in place by {@link #reconfigure}; read by every worker at each decision. */
    private volatile Settings settings;
    private final Logger log;
    private final StallWatchdog watchdog;

    private final ConcurrentLinkedQueue<ConsumerChannel> ready = new ConcurrentLinkedQueue<>();
    /** Parked workers, most recently parked first: waking that one finds warm caches and lets the others retire. */
    private final ConcurrentLinkedDeque<DeliveryWorker> parked = new ConcurrentLinkedDeque<>();
    /** Workers polling the run queue before they park: while there is one, a publisher need not wake anybody. */
    private final AtomicInteger spinning = new AtomicInteger();
    /** Workers started and not ended, stalled or not. */
    private final AtomicInteger workerCount = new AtomicInteger();
    private final List<DeliveryWorker> workers = new CopyOnWriteArrayList<>();
    private final AtomicInteger names = new AtomicInteger();
    private volatile int stalled;
    private volatile boolean running = true;

    DeliveryPool(Settings settings, Logger log) {
        this.settings = settings;
        this.log = log;
        this.watchdog = new StallWatchdog(this, settings.stallThresholdNanos(), settings.stallWarningNanos(), log);
    }

    /** Start the configured number of workers and the watchdog. */
    void start() {
        ensureWorkers();
        watchdog.start();
    }

    /** Stop: workers finish their turn and the turns already queued (closed channels clean up), then end. */
    void shutdown() {
        running = false;
        watchdog.stop();
        for (DeliveryWorker worker : workers) {
            LockSupport.unpark(worker.thread);
        }
    }

    /**
     * New settings, applied in place: more workers start at once; surplus workers retire once idle (parked ones
     * are woken to notice); the stall threshold and idle spin apply from the next inspection or idle period.
     */
    void reconfigure(Settings newSettings) {
        int before = settings.workers();
        settings = newSettings;
        watchdog.threshold(newSettings.stallThresholdNanos(), newSettings.stallWarningNanos());
        if (newSettings.workers() > before) {
            ensureWorkers();
        } else if (newSettings.workers() < before) {
            for (DeliveryWorker worker : parked) {
                LockSupport.unpark(worker.thread);
            }
        }
    }

    /** Put a channel whose token the caller holds at the end of the run queue. */
    void ready(ConsumerChannel channel) {
        ready.offer(channel);
    }

    /** Make sure a worker will look at the run queue soon: wakes at most one. */
    void signal() {
        if (spinning.get() == 0) {
            DeliveryWorker worker = parked.pollFirst();
            if (worker != null) {
                LockSupport.unpark(worker.thread);
            }
        }
    }

    /** The next turn for a worker, waiting for one; {@code null} when the worker is to end. */
    ConsumerChannel take(DeliveryWorker worker) {
        ConsumerChannel channel = ready.poll();
        if (channel == null) {
            channel = awaitReady(worker);
            if (channel == null) {
                return null;
            }
        }
        if (!ready.isEmpty()) {
            signal(); // more behaviours are waiting: pass the wake-up on rather than let the publisher pay it
        }
        return channel;
    }

    private ConsumerChannel awaitReady(DeliveryWorker worker) {
        ConsumerChannel channel = spin();
        boolean retired = false;
        while (channel == null && running && !retired) {
            parked.addFirst(worker);
            channel = ready.poll();
            if (channel != null || !running) {
                parked.remove(worker);
                break;
            }
            // Timed, so that a worker beyond the configured number notices it is no longer needed.
            LockSupport.parkNanos(this, settings.keepAliveNanos());
            boolean notWoken = parked.remove(worker); // false: a publisher popped us to take a turn
            channel = ready.poll();
            if (channel == null && running && notWoken) {
                retired = retireIfSurplus(); // counted out there
            }
        }
        if (channel == null && !retired) {
            // Stopping. The bus queues the last turns of its closed behaviours before it stops the pool, so a
            // poll after seeing the pool stopped finds any of them this worker's earlier polls missed: without
            // it, a worker woken for such a turn could end and leave the behaviour never given back.
            channel = ready.poll();
            if (channel == null) {
                workerCount.decrementAndGet();
            }
        }
        return channel;
    }

    /**
     * Parking costs the publisher a wake-up (a system call) and the worker a trip through the OS scheduler, which
     * at high rates costs more than the delivery itself. So an idle worker first spins, then yields its core for a
     * short while (events usually keep coming in a burst), and parks only after {@code idleSpinNanos}.
     */
    private ConsumerChannel spin() {
        spinning.incrementAndGet();
        try {
            for (int i = 0; i < SPINS; i++) {
                Thread.onSpinWait();
                ConsumerChannel channel = ready.poll();
                if (channel != null) {
                    return channel;
                }
            }
            long idleSince = System.nanoTime();
            while (running && System.nanoTime() - idleSince < settings.idleSpinNanos()) {
                Thread.yield();
                ConsumerChannel channel = ready.poll();
                if (channel != null) {
                    return channel;
                }
            }
            return null;
        } finally {
            spinning.decrementAndGet();
        }
    }

    private boolean retireIfSurplus() {
        while (true) {
            int count = workerCount.get();
            if (count - stalled <= settings.workers()) {
                return false;
            }
            if (workerCount.compareAndSet(count, count - 1)) {
                return true;
            }
        }
    }

    /** Start workers until the configured number of them are not stalled. */
    void ensureWorkers() {
        while (running) {
            int count = workerCount.get();
            if (count - stalled >= settings.workers()) {
                return;
            }
            if (workerCount.compareAndSet(count, count + 1)) {
                DeliveryWorker worker = new DeliveryWorker(this, watchdog, names.incrementAndGet());
                workers.add(worker);
                try {
                    worker.thread.start();
                } catch (OutOfMemoryError | RuntimeException e) {
                    workers.remove(worker);
                    workerCount.decrementAndGet();
                    log.error("The event bus could not start a delivery worker; behaviours may wait.", e);
                    return;
                }
            }
        }
    }

    /** Called by a worker as it ends: {@code expected} after {@link #take} returned null, false when it failed. */
    void exited(DeliveryWorker worker, boolean expected) {
        workers.remove(worker);
        if (!expected) {
            workerCount.decrementAndGet();
            log.error("Delivery worker {} of the event bus ended on an unexpected error; another one replaces it.",
                    worker.thread.getName());
            ensureWorkers();
        }
    }

    /** Set by the watchdog after each inspection. */
    void stalledWorkers(int count) {
        stalled = count;
    }

    List<DeliveryWorker> workers() {
        return workers;
    }

    /** Workers alive (stalled or not), for tests and statistics. */
    int workerCount() {
        return workerCount.get();
    }

    boolean isRunning() {
        return running;
    }
}
