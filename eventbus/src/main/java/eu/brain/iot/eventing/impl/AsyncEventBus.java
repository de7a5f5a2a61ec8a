package eu.brain.iot.eventing.impl;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;
import eu.brain.iot.eventing.impl.EventHold.Held;
import eu.brain.iot.eventing.impl.RouteTable.Route;
import eu.brain.iot.eventing.spi.HeldType;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * The bus core, free of OSGi wiring so that it can be tested and benchmarked on its own.
 * <p>
 * {@code deliver} runs on the publisher's thread: it snapshots the event, finds its route, reserves a slot in the
 * queue of every target behaviour (all or none, waiting up to the overflow timeout; a stalled behaviour is
 * skipped, see {@link StallPolicy}), queues the snapshot, and
 * wakes at most one delivery worker. The workers of the {@link DeliveryPool} then take turns on the behaviours
 * with queued events: each makes its behaviour's copy and calls it (see {@link ConsumerChannel}).
 * <p>
 * An event that no behaviour takes is put to the {@link UnhandledEventPolicy}, if there is one, on the
 * publisher's thread and outside any lock; what it asks to hold joins the {@link EventHold}. When a behaviour is
 * added, the held events it takes are moved into its queue in the same critical section that publishes the new
 * route table, and a publisher about to hold an event checks under that lock that the table it routed with is
 * still current (else it routes again): so held events are never overtaken, lost or delivered twice.
 * <p>
 * Ownership: {@link #routes} is replaced, never changed, under {@link #consumersLock}, which also guards
 * {@link #channels}, {@link #hold} and changes of {@link #policy}; publishers read {@link #routes} and
 * {@link #policy} without locking. Waiters for room in the hold wait on {@link #consumersLock}, which is notified
 * whenever the hold shrinks or the table or the policy changes. The settings are volatile and changed in place by
 * {@link #reconfigure}. The pool lives as long as the bus.
 */
final class AsyncEventBus implements EventBus {

    private final String sourceNode;
    private volatile int queueCapacity;
    private volatile long overflowTimeoutNanos;
    private final DeliveryPool pool;
    private final Logger log;

    private final Object consumersLock = new Object();
    private final Map<Long, ConsumerChannel> channels = new LinkedHashMap<>();
    private volatile RouteTable routes = new RouteTable(List.of());
    private final EventHold hold = new EventHold();
    private volatile UnhandledEventPolicy policy;
    private final PolicyAsker asker;
    private final ConcurrentHashMap<String, EventTypeCounters> counters = new ConcurrentHashMap<>();

    AsyncEventBus(String sourceNode, int queueCapacity, long overflowTimeoutMillis, DeliveryPool.Settings delivery,
            Logger log) {
        checkCapacity(queueCapacity);
        this.sourceNode = sourceNode;
        this.queueCapacity = queueCapacity;
        this.overflowTimeoutNanos = TimeUnit.MILLISECONDS.toNanos(Math.max(0, overflowTimeoutMillis));
        this.log = log;
        this.asker = new PolicyAsker(log);
        this.pool = new DeliveryPool(delivery, log);
        pool.start();
    }

    @Override
    public void deliver(BrainIoTEvent event) {
        publish(event, true);
    }

    @Override
    public void deliver(String eventType, Map<String, Object> eventData) {
        publish(eventType, eventData, true);
    }

    @Override
    public boolean tryDeliver(BrainIoTEvent event) {
        return publish(event, false);
    }

    @Override
    public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
        return publish(eventType, eventData, false);
    }

    /**
     * @param wait whether to wait for room (up to the overflow timeout, then throw) or to return false at once
     * @return whether the event was accepted (queued, held, or counted as unhandled)
     */
    private boolean publish(BrainIoTEvent event, boolean wait) {
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
        ConsumerChannel[] targets = route.targets(snapshot);
        if (targets.length > 0) {
            return send(targets, route, snapshot, wait, null); // the hot path: no hold, no policy, no lock
        }
        return unhandled(table, route, snapshot, snapshot.getClass(), null, wait, null);
    }

    private boolean publish(String eventType, Map<String, Object> eventData, boolean wait) {
        if (eventType == null || eventType.isEmpty() || eventData == null) {
            throw new IllegalArgumentException("deliver(eventType, eventData): both are required, got eventType="
                    + eventType + ", eventData=" + (eventData == null ? "null" : "a map"));
        }
        Map<String, Object> snapshot = EventMaps.copyMap(eventData);
        snapshot.putIfAbsent("sourceNode", sourceNode);
        snapshot.putIfAbsent("timestamp", Instant.now());
        RouteTable table = routes;
        Route route = table.routeFor(eventType, this::countersFor);
        ConsumerChannel[] targets = route.targets(snapshot);
        if (targets.length > 0) {
            return send(targets, route, snapshot, wait, null);
        }
        return unhandled(table, route, snapshot, null, null, wait, null);
    }

    /**
     * An event from another node: routed to local behaviours only (never to a forwarder), never waiting; with
     * {@code behavioursOnly}, not accepted when no behaviour takes it (RemoteEvents#tryDeliverRemoteToBehaviours).
     */
    boolean publishRemote(String eventType, List<String> typeNames, Map<String, Object> eventData, Runnable done,
            boolean behavioursOnly) {
        if (eventType == null || eventType.isEmpty() || eventData == null || done == null) {
            throw new IllegalArgumentException("tryDeliverRemote: eventType, eventData and done are required, got "
                    + "eventType=" + eventType);
        }
        List<String> names = RouteTable.remoteNames(eventType, typeNames);
        Map<String, Object> snapshot = EventMaps.copyMap(eventData);
        RouteTable table = routes;
        Route route = table.routeForRemote(eventType, names, this::countersFor);
        ConsumerChannel[] targets = route.targets(snapshot);
        if (targets.length > 0) {
            return send(targets, route, snapshot, false, done);
        }
        return !behavioursOnly && unhandled(table, route, snapshot, null, names, false, done);
    }

    /**
     * The route of an event in a table; {@code type} is null for an untyped event, {@code remoteNames} null for
     * a local one.
     */
    Route routeOf(RouteTable table, Class<?> type, String eventType, List<String> remoteNames) {
        if (remoteNames != null) {
            return table.routeForRemote(eventType, remoteNames, this::countersFor);
        }
        return type != null ? table.routeFor(type, this::countersFor) : table.routeFor(eventType, this::countersFor);
    }

    private ConsumerChannel[] targetsIn(RouteTable table, Held held) {
        return EventHold.without(routeOf(table, held.type(), held.counters().eventType, held.remoteNames())
                .targets(held.snapshot()), held.reached());
    }

    /**
     * Queue an event for its targets, all or none, waiting for room up to the overflow timeout if {@code wait}.
     *
     * @return false when a queue was full and {@code wait} is false (nothing queued then)
     */
    boolean send(ConsumerChannel[] targets, Route route, Object snapshot, boolean wait, Runnable done) {
        EventTypeCounters typeCounters = route.counters();
        ConsumerChannel[] reserved = Reservations.reserveAll(targets, typeCounters, wait, overflowTimeoutNanos,
                queueCapacity);
        if (reserved == null) {
            return false;
        }
        typeCounters.published.increment();
        Envelope envelope = new Envelope(snapshot, typeCounters, reserved.length == 1, route.typeNames(),
                done == null ? null : new Completion(reserved.length, done, log), wait, reserved);
        boolean madeReady = false;
        for (ConsumerChannel target : reserved) {
            madeReady |= target.enqueueFromPublisher(envelope);
        }
        if (madeReady) {
            pool.signal(); // once per event, not once per behaviour: workers pass the wake-up on
        }
        return true;
    }

    /**
     * An event that no behaviour takes in {@code table}: asks the unhandled-event policy (outside any lock, once
     * per event) and holds it, or follows the bus's own rules. Holding re-checks the table under the lock; when
     * it changed since, the event is routed again (with the same answer of the policy), so that it can neither
     * be appended to the hold after a hand-over nor overtake held events.
     */
    boolean unhandled(RouteTable table, Route route, Object snapshot, Class<?> type, List<String> remoteNames,
            boolean wait, Runnable done) {
        Disposition decided = null;
        long deadline = 0;
        while (true) {
            UnhandledEventPolicy current = policy;
            if (current == null) {
                return lastResortOrUnhandled(table, route, snapshot, wait, done);
            }
            if (decided == null) {
                decided = asker.ask(current, route, snapshot);
            }
            if (decided == Disposition.UNHANDLED) {
                route.counters().countUnhandled(log, "the unhandled-event policy " + current.getClass().getName()
                        + " gives them up");
                Completion.run(done, log);
                return true;
            }
            if (decided != Disposition.HOLD) {
                return lastResortOrUnhandled(table, route, snapshot, wait, done);
            }
            if (deadline == 0) {
                deadline = System.nanoTime() + overflowTimeoutNanos;
            }
            Held held = new Held(snapshot, type, route.counters(), System.currentTimeMillis(), remoteNames, null);
            HoldOutcome outcome = hold(table, current, held, wait ? deadline : 0);
            if (outcome == HoldOutcome.HELD) {
                Completion.run(done, log);
                return true;
            }
            if (outcome == HoldOutcome.FULL) {
                return false;
            }
            if (outcome == HoldOutcome.POLICY_CHANGED) {
                decided = null; // another policy, or none, decides now
            }
            table = routes;
            route = routeOf(table, type, route.counters().eventType, remoteNames);
            ConsumerChannel[] targets = route.targets(snapshot);
            if (targets.length > 0) {
                return send(targets, route, snapshot, wait, done);
            }
        }
    }

    private enum HoldOutcome { HELD, FULL, TABLE_CHANGED, POLICY_CHANGED }

    /**
     * Append to the hold if {@code table} and {@code current} are still current, waiting for room if full;
     * {@code deadline} 0: no waiting, {@link HoldOutcome#FULL} at once.
     */
    private HoldOutcome hold(RouteTable table, UnhandledEventPolicy current, Held held, long deadline) {
        int max = Math.max(1, current.maxHeldEvents()); // asked outside the lock, as every call of the policy
        synchronized (consumersLock) {
            while (true) {
                if (routes != table) {
                    return HoldOutcome.TABLE_CHANGED;
                }
                if (policy != current) {
                    return HoldOutcome.POLICY_CHANGED;
                }
                if (hold.size() < max) {
                    hold.append(held);
                    held.counters().published.increment();
                    return HoldOutcome.HELD;
                }
                if (deadline == 0) {
                    return HoldOutcome.FULL;
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw Overflows.holdFull(held.counters().eventType, max, current.getClass().getName(),
                            TimeUnit.NANOSECONDS.toMillis(overflowTimeoutNanos));
                }
                try {
                    // woken (notifyAll) whenever the hold shrinks or the table or the policy changes
                    TimeUnit.NANOSECONDS.timedWait(consumersLock, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw Overflows.interrupted(held.counters().eventType);
                }
            }
        }
    }

    /** The bus's own rules for an event no behaviour takes: consumers of last resort, else counted unhandled. */
    private boolean lastResortOrUnhandled(RouteTable table, Route route, Object snapshot, boolean wait,
            Runnable done) {
        if (table.lastResort.length > 0) {
            return send(table.lastResort, route, snapshot, wait, done);
        }
        route.counters().countUnhandled(log, "no consumer of last resort is installed");
        Completion.run(done, log);
        return true;
    }

    EventTypeCounters countersFor(String eventType) {
        return counters.computeIfAbsent(eventType, EventTypeCounters::new);
    }

    private static void checkCapacity(int queueCapacity) {
        if (queueCapacity < 1) {
            throw new IllegalArgumentException("queue capacity must be at least 1, was " + queueCapacity);
        }
    }

    /** The route table, once a change under way is published (a forwarder is closed and left out under the lock). */
    RouteTable settledRoutes() {
        synchronized (consumersLock) {
            return routes;
        }
    }

    /** Start delivering to a behaviour (see {@link #newTable}). */
    void addConsumer(ConsumerSpec spec) {
        ConsumerChannel channel = new ConsumerChannel(spec, queueCapacity, pool, log,
                spec.forwarder() ? new Orphans(this, log) : null);
        Runnable after;
        synchronized (consumersLock) {
            after = newTable(channels.put(spec.serviceId(), channel));
        }
        after.run();
    }

    /** Stop delivering to a behaviour; its queued events are discarded and counted, a forwarder's kept (below). */
    void removeConsumer(long serviceId) {
        Runnable after;
        synchronized (consumersLock) {
            ConsumerChannel channel = channels.remove(serviceId);
            if (channel == null) {
                return;
            }
            after = newTable(channel);
        }
        after.run();
    }

    /**
     * Publish the table of the current channels (under the lock), closing the one that left, if any. The held
     * events the new table routes are moved into their queues before it is published, a left forwarder's queued
     * events among them: every publisher that can reach those behaviours queues behind them, and a forwarder's
     * events that nobody takes now stay in the hold ahead of every event published after.
     *
     * @return what to do once the lock is released
     */
    private Runnable newTable(ConsumerChannel left) {
        RouteTable next = new RouteTable(channels.values());
        List<Held> queued = left == null ? List.of() : Orphans.held(left.closeAndTakeQueued());
        queued.forEach(hold::append);
        boolean madeReady = hold.size() > 0 && hold.handOver(held -> targetsIn(next, held));
        List<Held> orphans = hold.stillHeld(queued);
        routes = next;
        UnhandledEventPolicy current = policy;
        consumersLock.notifyAll(); // publishers waiting for room in the hold: re-check
        return () -> {
            if (madeReady) {
                pool.signal();
            }
            settleOrphans(orphans, current);
        };
    }

    /**
     * A left forwarder's events that nobody takes now: the policy is asked about them, once per type and outside
     * the lock, as about any unhandled event; they stay held if it says so, else follow the bus's own rules.
     */
    private void settleOrphans(List<Held> orphans, UnhandledEventPolicy current) {
        if (orphans.isEmpty()) {
            return;
        }
        Map<String, Disposition> decided = asker.askPerType(current, orphans,
                h -> routeOf(routes, h.type(), h.counters().eventType, null));
        boolean madeReady;
        synchronized (consumersLock) {
            List<Held> released = hold.take(orphans, h -> decided.get(h.counters().eventType) != Disposition.HOLD);
            RouteTable table = routes;
            madeReady = EventHold.dispatch(released, held -> targetsIn(table, held), table.lastResort,
                    held -> decided.get(held.counters().eventType) != Disposition.UNHANDLED,
                    counters -> counters.logUnhandled(log,
                            "nothing takes them since the node they were queued for left"));
            consumersLock.notifyAll();
        }
        if (madeReady) {
            pool.signal();
        }
    }

    /** Follow this policy from now on (it replaces any other: the component binds the highest-ranked one). */
    void policy(UnhandledEventPolicy newPolicy) {
        synchronized (consumersLock) {
            policy = newPolicy;
            consumersLock.notifyAll();
        }
    }

    /**
     * This policy went away: if it was the current one, its held events are dispatched by the bus's own rules
     * (consumers of last resort, else counted unhandled), in hold order, never silently dropped.
     */
    void policyGone(UnhandledEventPolicy gone) {
        boolean madeReady = false;
        synchronized (consumersLock) {
            if (policy != gone) {
                return; // replaced by a higher-ranked policy first: that one keeps the hold
            }
            policy = null;
            RouteTable table = routes;
            madeReady = EventHold.dispatch(hold.removeAll(), held -> targetsIn(table, held), table.lastResort,
                    held -> true,
                    counters -> counters.logUnhandled(log, "the unhandled-event policy that held them went away"));
            consumersLock.notifyAll();
        }
        if (madeReady) {
            pool.signal();
        }
    }

    /** @see eu.brain.iot.eventing.spi.HeldEvents#held() */
    List<HeldType> held() {
        synchronized (consumersLock) {
            return hold.types();
        }
    }

    /** @see eu.brain.iot.eventing.spi.HeldEvents#discard(String, String) */
    int discard(String eventType, String reason) {
        List<Held> discarded;
        synchronized (consumersLock) {
            discarded = hold.remove(eventType);
            consumersLock.notifyAll();
        }
        if (!discarded.isEmpty()) {
            discarded.get(0).counters().unhandled.add(discarded.size());
            log.warn("{} held events of type {} were given up ({}); they are counted as 'unhandled' (Gogo: "
                    + "bus:stats).", discarded.size(), eventType, reason);
        }
        return discarded.size();
    }

    /**
     * Apply new settings in place: queued and held events stay. The queue capacity applies to the next
     * reservations of every behaviour (a lower one makes publishers wait until a queue drains below it).
     */
    void reconfigure(int newQueueCapacity, long newOverflowTimeoutMillis, DeliveryPool.Settings delivery) {
        checkCapacity(newQueueCapacity);
        overflowTimeoutNanos = TimeUnit.MILLISECONDS.toNanos(Math.max(0, newOverflowTimeoutMillis));
        synchronized (consumersLock) {
            queueCapacity = newQueueCapacity;
            channels.values().forEach(c -> c.capacity(newQueueCapacity));
        }
        pool.reconfigure(delivery);
    }

    /**
     * Stop delivering: behaviours are closed first, so that the workers clean them up before they end. Held
     * events are counted as unhandled and logged.
     */
    void close() {
        List<Held> held;
        synchronized (consumersLock) {
            channels.values().forEach(ConsumerChannel::close);
            channels.clear();
            routes = new RouteTable(List.of());
            policy = null; // what a closing forwarder leaves is then counted unhandled, not held after the hold went
            held = hold.removeAll();
            consumersLock.notifyAll();
        }
        pool.shutdown();
        held.forEach(h -> h.counters().unhandled.increment());
        if (!held.isEmpty()) {
            log.warn("The event bus stopped with {} held events (waiting for behaviours to be installed); they were "
                    + "counted as 'unhandled'.", held.size());
        }
    }

    /** The delivery workers alive, stalled or not. */
    int workerCount() {
        return pool.workerCount();
    }

    List<EventTypeStatistics> eventTypes() {
        return new ArrayList<>(counters.values().stream().map(EventTypeCounters::snapshot)
                .sorted(Comparator.comparing((EventTypeStatistics s) -> s.eventType)).toList());
    }

    List<ConsumerStatistics> consumers() {
        List<ConsumerChannel> current;
        synchronized (consumersLock) {
            current = new ArrayList<>(channels.values());
        }
        return new ArrayList<>(current.stream().map(ConsumerChannel::statistics).sorted(Comparator
                .comparing((ConsumerStatistics s) -> s.consumer).thenComparingLong(s -> s.serviceId)).toList());
    }

}
