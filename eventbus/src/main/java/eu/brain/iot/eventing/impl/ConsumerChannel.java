package eu.brain.iot.eventing.impl;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;

/**
 * The queue of one behaviour, and its turns on the delivery workers of the {@link DeliveryPool}.
 * <p>
 * Scheduling: {@link #scheduled} is the behaviour's turn token. The publisher that queues an event into an idle
 * channel takes the token and puts the channel into the pool's run queue; a worker takes it from there, delivers
 * up to {@link #BATCH} events ({@link #runTurn}), then either puts it back at the end of the run queue (events
 * remain: one busy behaviour cannot starve the others) or gives the token back. Only the token holder delivers,
 * so a behaviour is never called twice at once, and since it takes events from one FIFO queue, it sees them in
 * publish order (per publishing thread).
 * <p>
 * Ownership: publishers only append to {@link #queue}, reserve room through {@link #offered}, may take a free
 * token, and consult the {@link StallPolicy} (its own lock) when the queue is full. Everything else ({@link #taken}, the {@link BehaviourCaller} with the behaviour object and its caches)
 * belongs to the token holder. {@link #runner} is written by the holder's worker and, to interrupt it, by
 * {@link #close}. Once closed, the token is never given back: the last holder discards what is queued and gives
 * the behaviour object back, exactly once.
 * <p>
 * Memory is bounded by {@code capacity}: {@code offered - taken} never exceeds it, except by the events handed
 * over from the bus's hold ({@link #forceReserve}), which the hold's own bound limits.
 */
final class ConsumerChannel {

    /**
     * Events a worker delivers to one behaviour per turn: large enough to amortise the scheduling (a few atomic
     * operations per turn), small enough that other behaviours get a turn soon.
     */
    static final int BATCH = 64;

    /** The value of {@link #runner} while {@link #close} interrupts the worker; see {@link #leaveTurn}. */
    private static final Object INTERRUPTING = new Object();
    private static final VarHandle SCHEDULED;
    private static final VarHandle RUNNER;

    static {
        try {
            MethodHandles.Lookup lookup = MethodHandles.lookup();
            SCHEDULED = lookup.findVarHandle(ConsumerChannel.class, "scheduled", boolean.class);
            RUNNER = lookup.findVarHandle(ConsumerChannel.class, "runner", Object.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    final ConsumerSpec spec;
    private final Orphans orphans;
    /** Changed in place by a reconfiguration of the bus; applies to the next reservations. */
    private volatile int capacity;
    private final DeliveryPool pool;
    private final Logger log;
    private final BehaviourCaller caller;
    private final StallPolicy stall;
    /** When the consumer was registered (epoch ms): an event published before cannot have reached it. */
    final long createdMillis = System.currentTimeMillis();

    private final ConcurrentLinkedQueue<Envelope> queue = new ConcurrentLinkedQueue<>();
    /**
     * For a forwarder: taken to queue, to take from the queue and to take what is left when it is closed, so that
     * the events it leaves behind keep their order before those published after (see {@link #closeAndTakeQueued}).
     */
    private final Object forwarderLock = new Object();
    /** Slots reserved by publishers; incremented before an envelope is queued. */
    private final AtomicLong offered = new AtomicLong();
    /**
     * Envelopes taken off the queue; written by the token holder only, with ordered (release) writes, which are
     * cheap on the hot path; readers may see a slightly old value, which only makes them more careful.
     */
    private final AtomicLong taken = new AtomicLong();
    /**
     * Publishers' last reading of {@link #taken}: re-read only when the queue looks full, so that publishers do
     * not pull the delivering worker's cache line on every event. A stale value errs on the safe side.
     */
    private volatile long takenSeen;
    /** The turn token: set while the channel waits in the run queue or a worker delivers its events. */
    private volatile boolean scheduled;
    private volatile boolean closed;
    /** Whether the warning about discarded events was logged; set by whoever discards first. */
    private final AtomicBoolean discardLogged = new AtomicBoolean();
    /** The worker thread inside a turn, {@link #INTERRUPTING}, or {@code null}. */
    private volatile Object runner;

    ConsumerChannel(ConsumerSpec spec, int capacity, DeliveryPool pool, Logger log) {
        this(spec, capacity, pool, log, null);
    }

    /**
     * @param orphans for a forwarder: takes the events still queued when it goes away (they are published again, to
     *        whoever takes them now), instead of discarding them; {@code null} for a behaviour
     */
    ConsumerChannel(ConsumerSpec spec, int capacity, DeliveryPool pool, Logger log, Orphans orphans) {
        this.orphans = orphans;
        this.spec = spec;
        this.capacity = capacity;
        this.pool = pool;
        this.log = log;
        this.caller = new BehaviourCaller(spec, log);
        this.stall = new StallPolicy(spec, log);
    }

    /** Reserve room for one envelope. @return false when the queue is full (nothing reserved then) */
    boolean tryReserve() {
        long reserved = offered.incrementAndGet();
        if (reserved - takenSeen > capacity) {
            long current = taken.get();
            takenSeen = current;
            if (reserved - current > capacity) {
                offered.decrementAndGet();
                return false;
            }
        }
        return true;
    }

    /**
     * Reserve room for one envelope even beyond the capacity: only for events handed over from the bus's hold,
     * under the bus's lock, where waiting is not possible. The hold's own bound keeps this bounded.
     */
    void forceReserve() {
        offered.incrementAndGet();
    }

    /** A new capacity (bus reconfiguration): a lower one only makes publishers wait until the queue drains. */
    void capacity(int capacity) {
        this.capacity = capacity;
    }

    /**
     * The queue is full: whether publishers should skip this behaviour because it is stalled (see
     * {@link StallPolicy}) rather than wait for room.
     */
    boolean stalledWhenFull(long now, long timeoutNanos) {
        return stall.skip(taken.get(), now, timeoutNanos, capacity);
    }

    /** An event not queued for this behaviour because it is stalled: counted as discarded. */
    void skipped(EventTypeCounters counters) {
        stall.skipped(counters);
    }

    /** Give back a slot reserved for an event that will not be queued after all. */
    void release() {
        offered.decrementAndGet();
    }

    /**
     * Queue an envelope for which a slot was reserved.
     *
     * @return true if the channel was idle and is now in the run queue: the publisher then calls
     *         {@link DeliveryPool#signal()}, once per event however many behaviours it reached
     */
    boolean enqueue(Envelope envelope) {
        return enqueue(envelope, false);
    }

    /**
     * As {@link #enqueue}, by a publisher on its own thread outside the bus's locks: when this is a forwarder and
     * the publisher takes its turn token, the forwarder is offered the queued events right here
     * ({@link #publisherTurn}), sparing them a delivery worker's wake-up on their way to another node.
     */
    boolean enqueueFromPublisher(Envelope envelope) {
        return enqueue(envelope, orphans != null);
    }

    private boolean enqueue(Envelope envelope, boolean forwardHere) {
        if (orphans != null) {
            boolean queued;
            synchronized (forwarderLock) {
                queued = !closed && queue.offer(envelope);
            }
            if (!queued) {
                // The forwarder left after this publisher routed: published again now, before its next event
                // (outside the lock, which the bus takes under its own).
                orphans.publishAgain(envelope, envelope.publisherWaits);
                return false;
            }
        } else {
            queue.offer(envelope);
        }
        boolean madeReady = !scheduled && SCHEDULED.compareAndSet(this, false, true);
        if (madeReady) {
            if (forwardHere) {
                madeReady = publisherTurn();
            } else {
                pool.ready(this);
            }
        }
        if (closed) {
            // The behaviour left while we were queueing: its last turn may be over already, so count it now.
            discardPending();
        }
        return madeReady;
    }

    /**
     * A forwarder's turn on the thread of the publisher that took its token: up to {@link #BATCH} queued events,
     * each taken off the queue only once the forwarder took it without waiting
     * ({@link BehaviourCaller#forwardNow}), under the lock {@link #closeAndTakeQueued} takes, so that an event is
     * either forwarded or left to be published again, never both. What it refuses, and a closed forwarder's end,
     * go to a delivery worker as any turn does.
     *
     * @return whether the channel went to the run queue (the publisher then signals the pool)
     */
    private boolean publisherTurn() {
        for (int i = 0; i < BATCH; i++) {
            synchronized (forwarderLock) {
                Envelope envelope = closed ? null : queue.peek();
                if (envelope == null || !caller.forwardNow(envelope)) {
                    break;
                }
                queue.poll();
            }
            taken.lazySet(taken.get() + 1);
            if (stall.isStalled()) {
                stall.resumed();
            }
        }
        if (closed || !queue.isEmpty()) {
            pool.ready(this);
            return true;
        }
        scheduled = false;
        // as in settle(): a publisher or close() that found the token taken just before it was given back
        if ((closed || !queue.isEmpty()) && SCHEDULED.compareAndSet(this, false, true)) {
            pool.ready(this);
            return true;
        }
        return false;
    }

    boolean isClosed() {
        return closed;
    }

    int depth() {
        return (int) Math.max(0, offered.get() - taken.get());
    }

    /** Events taken so far: the stall watchdog's measure of progress inside a turn. */
    long takenCount() {
        return taken.get();
    }

    /** Stop delivering: queued events are discarded and counted, the behaviour object is given back. */
    void close() {
        closed = true;
        Object worker = runner;
        if (worker instanceof Thread thread && thread != Thread.currentThread()
                && RUNNER.compareAndSet(this, thread, INTERRUPTING)) {
            // A behaviour blocked in notify() is being taken away: wake it so that its worker comes back.
            thread.interrupt();
            runner = null;
        }
        if (!scheduled && SCHEDULED.compareAndSet(this, false, true)) {
            // Idle: a worker still has to give the behaviour object back, on a delivery thread as always.
            pool.ready(this);
            pool.signal();
        }
    }

    /**
     * Close a forwarder and take its queued events, in order (under the bus's lock, before the new route table is
     * published): from then on nothing is queued to it, and it delivers no more than an event it had taken already.
     * For a behaviour, just {@link #close()}: its queued events are discarded.
     */
    List<Envelope> closeAndTakeQueued() {
        List<Envelope> taken = new ArrayList<>();
        if (orphans != null) {
            synchronized (forwarderLock) {
                // closed and emptied in one step: whoever sees it closed finds nothing left to publish again
                closed = true;
                for (Envelope e = queue.poll(); e != null; e = queue.poll()) {
                    taken.add(e);
                }
            }
        }
        close();
        return taken;
    }

    /** A forwarder's next event, none once closed: closing and taking its queue cannot interleave with this. */
    private Envelope pollForwarder() {
        synchronized (forwarderLock) {
            return closed ? null : queue.poll();
        }
    }

    /** What a closed forwarder still holds: only what {@link #closeAndTakeQueued} did not take (the bus closed). */
    private Envelope pollClosedForwarder() {
        synchronized (forwarderLock) {
            return queue.poll();
        }
    }

    /** One turn, run by the worker that took this channel from the run queue (the token holder). */
    void runTurn() {
        Thread worker = Thread.currentThread();
        runner = worker;
        try {
            for (int i = 0; i < BATCH && !closed; i++) {
                Envelope envelope = orphans == null ? queue.poll() : pollForwarder();
                if (envelope == null) {
                    break;
                }
                taken.lazySet(taken.get() + 1);
                caller.call(envelope);
                if (stall.isStalled()) {
                    stall.resumed();
                }
            }
        } finally {
            leaveTurn(worker);
            settle();
        }
    }

    private void leaveTurn(Thread worker) {
        if (!RUNNER.compareAndSet(this, worker, null)) {
            // close() is interrupting this worker right now: wait until it has, so that its interrupt cannot
            // land in the next behaviour's notify().
            while (runner == INTERRUPTING) {
                Thread.onSpinWait();
            }
        }
        // An interrupt aimed at this behaviour, or left set by it, must not reach the next behaviour.
        Thread.interrupted();
    }

    /** End of a turn: requeue, give the token back, or, once closed, clean up for good. */
    private void settle() {
        if (closed) {
            retire();
            return;
        }
        if (!queue.isEmpty()) {
            pool.ready(this);
            return;
        }
        scheduled = false;
        // A publisher (or close()) may have found the token still taken just before we gave it back. Both sides
        // write first and read the other's state second, so at least one of them sees the other: look again.
        if ((closed || !queue.isEmpty()) && SCHEDULED.compareAndSet(this, false, true)) {
            if (closed) {
                retire();
            } else {
                pool.ready(this);
            }
        }
    }

    private void retire() {
        discardPending();
        caller.releaseBehaviour();
    }

    private void discardPending() {
        int count = 0;
        Envelope e;
        while ((e = orphans == null ? queue.poll() : pollClosedForwarder()) != null) {
            if (orphans != null) {
                orphans.publishAgain(e, false);
                continue;
            }
            e.counters.discarded.increment();
            e.consumed();
            count++;
        }
        if (count > 0 && discardLogged.compareAndSet(false, true)) {
            // once: publishers that meet the closed channel discard what they queued themselves
            log.warn("Smart behaviour {} (bundle {}) went away with {} queued events; they were discarded "
                    + "and counted as 'discarded' in the bus statistics.", spec.name(), spec.bundle(), count);
        }
    }

    ConsumerStatistics statistics() {
        ConsumerStatistics s = new ConsumerStatistics();
        s.consumer = spec.name();
        s.serviceId = spec.serviceId();
        s.bundle = spec.bundle();
        s.consumed = new ArrayList<>(spec.consumed());
        s.filter = spec.filter() == null ? "" : spec.filter().toString();
        s.lastResort = spec.lastResort();
        s.untyped = spec.untyped();
        s.queueDepth = depth();
        s.delivered = caller.delivered();
        s.failures = caller.failures();
        s.stalled = stall.isStalled();
        s.discarded = stall.discarded();
        return s;
    }
}
