package eu.brain.iot.eventing.impl;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;
import eu.brain.iot.eventing.impl.RouteTable.Route;

/**
 * The bus core, free of OSGi wiring so that it can be tested and benchmarked on its own.
 * <p>
 * {@code deliver} runs on the publisher's thread: it snapshots the event, finds its route, reserves a slot in the
 * queue of every target behaviour (all or none, waiting up to the overflow timeout), queues the snapshot, and
 * wakes at most one delivery worker. The workers of the {@link DeliveryPool} then take turns on the behaviours
 * with queued events: each makes its behaviour's copy and calls it (see {@link ConsumerChannel}).
 * <p>
 * Ownership: {@link #routes} is replaced, never changed, under {@link #consumersLock}, which also guards
 * {@link #channels}; publishers read {@link #routes} without locking. The pool lives as long as the bus.
 */
final class AsyncEventBus implements EventBus {

    private static final ConsumerChannel[] NONE = new ConsumerChannel[0];

    private final String sourceNode;
    private final int queueCapacity;
    private final long overflowTimeoutNanos;
    private final DeliveryPool pool;
    private final Logger log;

    private final Object consumersLock = new Object();
    private final Map<Long, ConsumerChannel> channels = new LinkedHashMap<>();
    private volatile RouteTable routes = RouteTable.EMPTY;
    private final ConcurrentHashMap<String, EventTypeCounters> counters = new ConcurrentHashMap<>();

    AsyncEventBus(String sourceNode, int queueCapacity, long overflowTimeoutMillis, DeliveryPool.Settings delivery,
            Logger log) {
        if (queueCapacity < 1) {
            throw new IllegalArgumentException("queue capacity must be at least 1, was " + queueCapacity);
        }
        this.sourceNode = sourceNode;
        this.queueCapacity = queueCapacity;
        this.overflowTimeoutNanos = TimeUnit.MILLISECONDS.toNanos(Math.max(0, overflowTimeoutMillis));
        this.log = log;
        this.pool = new DeliveryPool(delivery, log);
        pool.start();
    }

    @Override
    public void deliver(BrainIoTEvent event) {
        if (event == null) {
            throw new IllegalArgumentException("deliver(null): an event is required");
        }
        BrainIoTEvent snapshot = EventCopier.copyEvent(event);
        if (snapshot.sourceNode == null) {
            snapshot.sourceNode = sourceNode;
        }
        if (snapshot.timestamp == null) {
            snapshot.timestamp = Instant.now();
        }
        RouteTable table = routes;
        Route route = table.routeFor(snapshot.getClass(), this::countersFor);
        dispatch(table, route, snapshot, route.filtered().length == 0 ? null : EventMaps.toMap(snapshot));
    }

    @Override
    public void deliver(String eventType, Map<String, Object> eventData) {
        if (eventType == null || eventType.isEmpty() || eventData == null) {
            throw new IllegalArgumentException("deliver(eventType, eventData): both are required, got eventType="
                    + eventType + ", eventData=" + (eventData == null ? "null" : "a map"));
        }
        Map<String, Object> snapshot = EventMaps.copyMap(eventData);
        snapshot.putIfAbsent("sourceNode", sourceNode);
        snapshot.putIfAbsent("timestamp", Instant.now());
        RouteTable table = routes;
        Route route = table.routeFor(eventType, this::countersFor);
        dispatch(table, route, snapshot, snapshot);
    }

    private void dispatch(RouteTable table, Route route, Object snapshot, Map<String, ?> fields) {
        ConsumerChannel[] targets = route.plain();
        if (route.filtered().length > 0) {
            targets = withMatchingFilters(targets, route.filtered(), fields);
        }
        EventTypeCounters typeCounters = route.counters();
        if (targets.length == 0) {
            targets = table.lastResort;
        }
        if (targets.length == 0) {
            typeCounters.published.increment();
            typeCounters.unhandled.increment();
            if (typeCounters.unhandledLogged.compareAndSet(false, true)) {
                log.warn("No smart behaviour consumes events of type {} and no consumer of last resort is "
                        + "installed; such events are counted as 'unhandled' (Gogo: bus:stats).",
                        typeCounters.eventType);
            }
            return;
        }
        reserveAll(targets, typeCounters.eventType);
        typeCounters.published.increment();
        Envelope envelope = new Envelope(snapshot, typeCounters, targets.length == 1);
        boolean madeReady = false;
        for (ConsumerChannel target : targets) {
            madeReady |= target.enqueue(envelope);
        }
        if (madeReady) {
            pool.signal(); // once per event, not once per behaviour: workers pass the wake-up on
        }
    }

    private static ConsumerChannel[] withMatchingFilters(ConsumerChannel[] plain, ConsumerChannel[] filtered,
            Map<String, ?> fields) {
        List<ConsumerChannel> targets = new ArrayList<>(Arrays.asList(plain));
        for (ConsumerChannel c : filtered) {
            if (c.spec.filter().matches(fields)) {
                targets.add(c);
            }
        }
        return targets.toArray(NONE);
    }

    /** Reserve a queue slot in every target, or none: waits for room up to the overflow timeout. */
    private void reserveAll(ConsumerChannel[] targets, String eventType) {
        long deadline = 0;
        for (int i = 0; i < targets.length; i++) {
            ConsumerChannel target = targets[i];
            while (!target.tryReserve()) {
                if (target.isClosed()) {
                    break; // it is leaving; the envelope will be counted as discarded
                }
                long now = System.nanoTime();
                if (deadline == 0) {
                    deadline = now + overflowTimeoutNanos;
                }
                if (now - deadline >= 0) {
                    for (int j = 0; j < i; j++) {
                        targets[j].release();
                    }
                    throw new EventBusOverflowException(eventType, target.spec.name(),
                            "Event of type " + eventType + " not delivered: the queue of smart behaviour "
                                    + target.spec.name() + " (bundle " + target.spec.bundle() + ") stayed full ("
                                    + queueCapacity + " events) for "
                                    + TimeUnit.NANOSECONDS.toMillis(overflowTimeoutNanos)
                                    + " ms. That behaviour is too slow or blocked; publish more slowly, fix it, "
                                    + "or raise queue.capacity in configuration PID " + EventBusComponent.PID + ".");
                }
                LockSupport.parkNanos(50_000);
            }
        }
    }

    private EventTypeCounters countersFor(String eventType) {
        return counters.computeIfAbsent(eventType, EventTypeCounters::new);
    }

    /** Start delivering to a behaviour. */
    void addConsumer(ConsumerSpec spec) {
        ConsumerChannel channel = new ConsumerChannel(spec, queueCapacity, pool, log);
        synchronized (consumersLock) {
            ConsumerChannel old = channels.put(spec.serviceId(), channel);
            routes = new RouteTable(channels.values());
            if (old != null) {
                old.close();
            }
        }
    }

    /** Stop delivering to a behaviour; its queued events are discarded and counted. */
    void removeConsumer(long serviceId) {
        synchronized (consumersLock) {
            ConsumerChannel channel = channels.remove(serviceId);
            if (channel != null) {
                routes = new RouteTable(channels.values());
                channel.close();
            }
        }
    }

    /** Stop delivering: behaviours are closed first, so that the workers clean them up before they end. */
    void close() {
        synchronized (consumersLock) {
            channels.values().forEach(ConsumerChannel::close);
            channels.clear();
            routes = RouteTable.EMPTY;
        }
        pool.shutdown();
    }

    /** The delivery workers alive, stalled or not. */
    int workerCount() {
        return pool.workerCount();
    }

    List<EventTypeStatistics> eventTypes() {
        List<EventTypeStatistics> list = new ArrayList<>();
        counters.values().forEach(c -> list.add(c.snapshot()));
        list.sort(Comparator.comparing(s -> s.eventType));
        return list;
    }

    List<ConsumerStatistics> consumers() {
        List<ConsumerChannel> current;
        synchronized (consumersLock) {
            current = new ArrayList<>(channels.values());
        }
        List<ConsumerStatistics> list = new ArrayList<>();
        current.forEach(c -> list.add(c.statistics()));
        list.sort(Comparator.comparing((ConsumerStatistics s) -> s.consumer).thenComparingLong(s -> s.serviceId));
        return list;
    }

}
