package eu.brain.iot.eventing.impl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;

/**
 * The queue and the delivery thread of one behaviour.
 * <p>
 * Ownership: publishers only append to {@link #queue} and reserve room through {@link #offered}; everything else
 * ({@link #taken}, the class caches, the failure log set, the calls into the behaviour) belongs to the channel's
 * own delivery thread. One thread per behaviour is what isolates behaviours from each other: a behaviour that
 * blocks holds only its own thread, and its events stay in publish order because a single thread takes them
 * from a FIFO queue.
 * <p>
 * Memory is bounded by {@code capacity}: {@code offered - taken} never exceeds it.
 */
final class ConsumerChannel {

    /** Spins before parking: cheap wake-up when events arrive back to back, no CPU burnt when idle. */
    private static final int SPINS = 64;

    final ConsumerSpec spec;
    private final int capacity;
    /** How long an idle delivery thread keeps yielding its core before it parks. */
    private final long idleNanos;
    private final Logger log;

    private final ConcurrentLinkedQueue<Envelope> queue = new ConcurrentLinkedQueue<>();
    /** Slots reserved by publishers; incremented before an envelope is queued. */
    private final AtomicLong offered = new AtomicLong();
    /**
     * Envelopes taken off the queue; written by the delivery thread only, with ordered (release) writes, which
     * are cheap on the hot path; readers may see a slightly old value, which only makes them more careful.
     */
    private final AtomicLong taken = new AtomicLong();
    /**
     * Publishers' last reading of {@link #taken}: re-read only when the queue looks full, so that publishers do
     * not pull the delivery thread's cache line on every event. A stale value errs on the safe side.
     */
    private volatile long takenSeen;
    private final AtomicLong delivered = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();
    /** Set by the delivery thread before it parks; publishers unpark it when they see it. */
    private volatile boolean waiting;
    private volatile boolean closed;
    private final Thread thread;

    // Owned by the delivery thread.
    /** The behaviour object, fetched on the first delivery. */
    private Object behaviour;
    private final Map<Class<?>, Class<?>> ownClassOf = new HashMap<>();
    /** Kept in a field: a method reference written at the call site would be allocated for every event. */
    private final java.util.function.Function<Class<?>, Class<?>> ownClassFunction = this::ownClass;
    private final Map<String, Class<?>> ownClassByName = new HashMap<>();
    private final Set<String> failureLogged = new HashSet<>();

    ConsumerChannel(ConsumerSpec spec, int capacity, long idleNanos, Logger log) {
        this.spec = spec;
        this.capacity = capacity;
        this.idleNanos = idleNanos;
        this.log = log;
        this.thread = new Thread(this::run, "brain-iot-bus[" + spec.name() + "]");
        this.thread.setDaemon(true);
    }

    void start() {
        thread.start();
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

    /** Give back a slot reserved for an event that will not be queued after all. */
    void release() {
        offered.decrementAndGet();
    }

    /** Queue an envelope for which a slot was reserved. */
    void enqueue(Envelope envelope) {
        queue.offer(envelope);
        if (waiting) {
            LockSupport.unpark(thread);
        }
        if (closed) {
            // The behaviour left while we were queueing: nobody will take this, so count it now.
            discardPending();
        }
    }

    boolean isClosed() {
        return closed;
    }

    int depth() {
        return (int) Math.max(0, offered.get() - taken.get());
    }

    /** Stop delivering: queued events are discarded and counted; the thread ends. */
    void close() {
        closed = true;
        LockSupport.unpark(thread);
        if (Thread.currentThread() != thread) {
            // A behaviour blocked in notify() is being taken away: wake it so that its thread can end.
            thread.interrupt();
        }
    }

    private void run() {
        while (!closed) {
            Envelope envelope = queue.poll();
            if (envelope == null) {
                envelope = awaitEnvelope();
                if (envelope == null) {
                    continue;
                }
            }
            taken.lazySet(taken.get() + 1);
            if (closed) {
                discard(envelope);
                break;
            }
            handle(envelope);
        }
        discardPending();
        if (behaviour != null) {
            behaviour = null;
            spec.target().release();
        }
    }

    private Envelope awaitEnvelope() {
        // Parking costs the publisher an unpark (a system call) per event, which at high rates with more
        // behaviours than cores costs more than the delivery itself. So an idle delivery thread first spins,
        // then yields its core for a short while (events usually keep coming in a burst), and parks only after
        // {@code idleNanos} without an event.
        for (int i = 0; i < SPINS; i++) {
            Thread.onSpinWait();
            Envelope e = queue.poll();
            if (e != null) {
                return e;
            }
        }
        long idleSince = System.nanoTime();
        while (System.nanoTime() - idleSince < idleNanos) {
            Thread.yield();
            Envelope e = queue.poll();
            if (e != null || closed) {
                return e;
            }
        }
        waiting = true;
        Envelope e = queue.poll();
        if (e == null && !closed) {
            LockSupport.park(this);
        }
        waiting = false;
        Thread.interrupted(); // an interrupt aimed at a notify() call must not end later parks early
        return e;
    }

    private void handle(Envelope envelope) {
        try {
            if (behaviour == null) {
                behaviour = spec.target().get();
                if (behaviour == null) {
                    throw new IllegalStateException("the behaviour service is no longer available");
                }
            }
            if (spec.untyped()) {
                ((UntypedSmartBehaviour) behaviour).notify(envelope.type(), toMap(envelope));
            } else {
                @SuppressWarnings("unchecked")
                SmartBehaviour<BrainIoTEvent> typed = (SmartBehaviour<BrainIoTEvent>) behaviour;
                typed.notify(toTyped(envelope));
            }
            delivered.lazySet(delivered.get() + 1);
            envelope.counters.delivered.increment();
        } catch (OutOfMemoryError e) {
            throw e;
        } catch (Throwable t) {
            failures.lazySet(failures.get() + 1);
            envelope.counters.failed.increment();
            if (failureLogged.add(envelope.type())) {
                log.error("Smart behaviour {} (bundle {}) failed on an event of type {}; it keeps receiving "
                        + "events, and further failures on this type are counted in the bus statistics "
                        + "(Gogo: bus:stats) rather than logged.", spec.name(), spec.bundle(), envelope.type(), t);
            }
        }
    }

    @SuppressWarnings("unchecked")
    private Map<String, ?> toMap(Envelope envelope) {
        return envelope.payload instanceof Map<?, ?> map
                ? EventMaps.copyMap((Map<String, ?>) map)
                : EventMaps.toMap(envelope.payload);
    }

    @SuppressWarnings("unchecked")
    private BrainIoTEvent toTyped(Envelope envelope) {
        if (envelope.payload instanceof BrainIoTEvent event) {
            Class<?> own = ownClassOf.computeIfAbsent(event.getClass(), ownClassFunction);
            if (own == event.getClass()) {
                return envelope.exclusive ? event : EventCopier.copyEvent(event);
            }
            return (BrainIoTEvent) EventMaps.convert(event, own);
        }
        Class<?> own = ownClassByName.computeIfAbsent(envelope.type(), spec.classes());
        if (own == null) {
            throw new IllegalStateException("bundle " + spec.bundle() + " cannot load the event class "
                    + envelope.type() + " that it declares it consumes");
        }
        return (BrainIoTEvent) EventMaps.fromMap((Map<String, ?>) envelope.payload, own);
    }

    /** The class this behaviour's bundle sees under the event class's name; the event's own class if none. */
    private Class<?> ownClass(Class<?> eventClass) {
        Class<?> own = spec.classes().apply(eventClass.getName());
        return own == null ? eventClass : own;
    }

    private void discardPending() {
        int count = 0;
        Envelope e;
        while ((e = queue.poll()) != null) {
            discard(e);
            count++;
        }
        if (count > 0) {
            log.warn("Smart behaviour {} (bundle {}) went away with {} queued events; they were discarded "
                    + "and counted as 'discarded' in the bus statistics.", spec.name(), spec.bundle(), count);
        }
    }

    private void discard(Envelope e) {
        e.counters.discarded.increment();
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
        s.delivered = delivered.get();
        s.failures = failures.get();
        return s;
    }
}
