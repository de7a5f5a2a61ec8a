package eu.brain.iot.eventing.impl;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.Collections;
import java.util.Set;
import java.util.WeakHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.osgi.service.log.Logger;

/**
 * Keeps behaviours isolated on a shared pool: every half threshold it looks at each worker, and a worker that
 * has stayed inside the same turn without taking another event counts as stalled (its behaviour is blocked or
 * slow in one {@code notify()} call). The pool then starts another worker, so the other behaviours keep
 * flowing; a stalled worker counts again as soon as it moves on.
 * <p>
 * What counts is time the behaviour holds the worker, not time the machine does. A worker stalls when it has
 * been in one call for the stall threshold and is now waiting (on a lock, a latch, a sleep, a full queue),
 * which is seen 1 to 1.5 thresholds after the call began. A worker whose thread Java reports as running stalls
 * only after {@value #RUNNING_FACTOR} thresholds, and only if it is in native code (blocking I/O) or used at
 * least one threshold of CPU time in that call (a long computation): a thread that is merely not scheduled (on
 * a busy machine a running thread can wait tens of milliseconds for a core) does not stall, since adding
 * workers then would only add threads when cores are short. Running threads get longer because the evidence is
 * weaker: a thread can be descheduled inside one of the JDK's short native methods, and in a virtual machine a
 * thread's CPU clock also runs while the host has taken the virtual CPU away (measured here: 5 ms of "CPU"
 * without progress under load). See {@link ThreadActivity}.
 * <p>
 * The worker's thread is renamed after the stalled behaviour while it is stalled, so that a thread dump
 * shows who holds it. A stall is logged (once per behaviour) only when the call has lasted the warning time
 * ({@code stall.warning.ms}): shorter ones are ordinary at a behaviour's first events (activation, class loading).
 * <p>
 * Costs: the workers write nothing for the watchdog on the event path (it reads the channel's {@code taken}
 * count); they write their current turn twice per turn. When no worker has been busy for a second, the
 * watchdog parks until a worker starts a turn, so an idle bus causes no wake-ups.
 * <p>
 * Ownership: this thread alone reads and writes every {@link Watch}, {@link #logged}, the stalled count it hands
 * to the pool, and the names of stalled workers. {@link #asleep} is set by this thread and cleared by whoever
 * wakes it.
 */
final class StallWatchdog implements Runnable {

    /** What the watchdog last saw of one worker. */
    static final class Watch {
        private ConsumerChannel channel;
        private int turn;
        private long taken;
        /** When the worker was first seen in this state. */
        private long since;
        /** Its CPU time when first seen still in this state, {@link #NOT_TAKEN}, or {@link ThreadActivity#UNKNOWN}. */
        private long cpuSince;
        private boolean stalled;
    }

    /** How many stall thresholds a worker whose thread is running may take; see the class comment. */
    static final int RUNNING_FACTOR = 4;
    private static final long NOT_TAKEN = Long.MIN_VALUE;
    private static final long SLEEP_AFTER_IDLE_NANOS = TimeUnit.SECONDS.toNanos(1);
    private static final long MIN_TICK_NANOS = TimeUnit.MICROSECONDS.toNanos(500);
    private static final VarHandle ASLEEP;

    static {
        try {
            ASLEEP = MethodHandles.lookup().findVarHandle(StallWatchdog.class, "asleep", boolean.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    private final DeliveryPool pool;
    /** Changed in place by a reconfiguration of the bus ({@link #threshold}); read by the watchdog thread. */
    private volatile long thresholdNanos;
    /** How long one call lasts before its stall is logged; changed in place like the threshold. */
    private volatile long warningNanos;
    private volatile long tickNanos;
    private final Logger log;
    private final Thread thread;
    /** Behaviours whose stall was logged; weak, so that behaviours that went away are forgotten. */
    private final Set<ConsumerChannel> logged = Collections.newSetFromMap(new WeakHashMap<>());
    private volatile boolean asleep;

    StallWatchdog(DeliveryPool pool, long thresholdNanos, long warningNanos, Logger log) {
        this.pool = pool;
        this.thresholdNanos = thresholdNanos;
        this.warningNanos = warningNanos;
        this.tickNanos = Math.max(MIN_TICK_NANOS, thresholdNanos / 2);
        this.log = log;
        this.thread = new Thread(this, "brain-iot-bus-watchdog");
        this.thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    /** A new stall threshold and warning time, applied from the next inspection on. */
    void threshold(long newThresholdNanos, long newWarningNanos) {
        tickNanos = Math.max(MIN_TICK_NANOS, newThresholdNanos / 2);
        thresholdNanos = newThresholdNanos;
        warningNanos = newWarningNanos;
        LockSupport.unpark(thread);
    }

    /** Called after the pool stopped running. */
    void stop() {
        LockSupport.unpark(thread);
    }

    /** Called by a worker as it starts a turn: one volatile read, plus a wake-up after a second of idleness. */
    void workerBusy() {
        if (asleep && ASLEEP.compareAndSet(this, true, false)) {
            LockSupport.unpark(thread);
        }
    }

    @Override
    public void run() {
        long last = System.nanoTime();
        long lastBusy = last;
        while (pool.isRunning()) {
            LockSupport.parkNanos(this, tickNanos);
            long now = System.nanoTime();
            // A watchdog that was itself held up (a GC pause, a starved machine) cannot tell a stuck behaviour
            // from a paused process: the time it was late by does not count towards a stall. Only that time:
            // restarting the clocks instead meant that on a busy machine, where late ticks are common, a blocked
            // behaviour could go unnoticed for as long as the ticks kept coming late.
            long lateNanos = Math.max(0, now - last - tickNanos);
            last = now;
            if (inspect(now, lateNanos)) {
                lastBusy = now;
            } else if (now - lastBusy >= SLEEP_AFTER_IDLE_NANOS) {
                sleepUntilBusy();
                last = lastBusy = System.nanoTime();
            }
        }
    }

    /** @return whether any worker was inside a turn */
    private boolean inspect(long now, long lateNanos) {
        boolean busy = false;
        int stalled = 0;
        for (DeliveryWorker worker : pool.workers()) {
            Watch watch = worker.watch;
            ConsumerChannel channel = worker.current();
            if (channel == null) {
                moved(worker);
                continue;
            }
            busy = true;
            int turn = worker.turns();
            long taken = channel.takenCount();
            if (channel != watch.channel || turn != watch.turn || taken != watch.taken) {
                moved(worker);
                watch.channel = channel;
                watch.turn = turn;
                watch.taken = taken;
                watch.since = now;
                watch.cpuSince = NOT_TAKEN;
            } else {
                watch.since = Math.min(now, watch.since + lateNanos);
                if (!watch.stalled && held(worker.thread, watch, now)) {
                    stalled(worker, channel);
                }
                if (watch.stalled && now - watch.since >= warningNanos && logged.add(channel)) {
                    warn(channel, now - watch.since);
                }
            }
            if (watch.stalled) {
                stalled++;
            }
        }
        pool.stalledWorkers(stalled);
        if (stalled > 0) {
            pool.ensureWorkers();
        }
        return busy;
    }

    /** Whether the worker, seen in the same call since {@code watch.since}, is held by its behaviour. */
    private boolean held(Thread thread, Watch watch, long now) {
        if (watch.cpuSince == NOT_TAKEN) {
            // Only for a worker seen twice in one call, so the CPU clock is rarely read.
            watch.cpuSince = ThreadActivity.cpuNanos(thread);
        }
        long inCall = now - watch.since;
        if (inCall < thresholdNanos) {
            return false;
        }
        if (ThreadActivity.waiting(thread)) {
            return true;
        }
        if (inCall < RUNNING_FACTOR * thresholdNanos) {
            return false;
        }
        // Running for a while: computing, in blocking I/O (native code), or just not scheduled (no CPU used).
        return watch.cpuSince == ThreadActivity.UNKNOWN || ThreadActivity.inNative(thread)
                || ThreadActivity.cpuNanos(thread) - watch.cpuSince >= thresholdNanos;
    }

    private void stalled(DeliveryWorker worker, ConsumerChannel channel) {
        worker.watch.stalled = true;
        worker.thread.setName("brain-iot-bus[" + channel.spec.name() + "] stalled in notify(), " + worker.name());
    }

    /** Once per behaviour: it has held its worker for the warning time (a stall, not ordinary start-up work). */
    private void warn(ConsumerChannel channel, long forNanos) {
        log.warn("Smart behaviour {} (bundle {}) has been inside one notify() call for {} ms (stall.warning.ms); "
                + "the event bus started another delivery worker so that the other behaviours keep receiving. Its "
                + "own events wait in its queue until it returns. Further stalls of this behaviour are not logged.",
                channel.spec.name(), channel.spec.bundle(), TimeUnit.NANOSECONDS.toMillis(forNanos));
    }

    /** The worker has left the turn it was seen in: it is not stalled (any more). */
    private static void moved(DeliveryWorker worker) {
        Watch watch = worker.watch;
        watch.channel = null;
        if (watch.stalled) {
            watch.stalled = false;
            worker.thread.setName(worker.name());
        }
    }

    private void sleepUntilBusy() {
        asleep = true;
        // A worker sets its turn, then reads 'asleep'; we set 'asleep', then read the turns: one of us sees
        // the other, so a turn that starts now is never left unwatched.
        boolean busy = false;
        for (DeliveryWorker worker : pool.workers()) {
            busy |= worker.current() != null;
        }
        if (!busy && pool.isRunning()) {
            LockSupport.park(this);
        }
        asleep = false;
    }
}
