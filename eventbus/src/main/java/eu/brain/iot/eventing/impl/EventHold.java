package eu.brain.iot.eventing.impl;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Predicate;

import eu.brain.iot.eventing.spi.HeldType;

/**
 * The bus's hold: events that no behaviour consumes and that the unhandled-event policy asked the bus to keep,
 * in one queue for all types, in publish order, until a behaviour that takes them is registered.
 * <p>
 * Ownership: every method must be called while holding the bus's lock (the one under which the route table is
 * replaced), which is what makes a hand-over and the publication of the new table one step: no publisher can
 * append to the hold or reach the new behaviour in between. The hold itself has no lock and no thread.
 */
final class EventHold {

    /**
     * One held event: the bus's snapshot (an event object, or a map for an untyped event), its class ({@code null}
     * when untyped: then it is routed by {@code counters.eventType}), when it was held, and for an event from
     * another node the type names it is routed by (to local behaviours only), else {@code null}; for an event a
     * forwarder left behind, the consumers it reached already (it goes to none of them again), else {@code null}.
     */
    record Held(Object snapshot, Class<?> type, EventTypeCounters counters, long since, List<String> remoteNames,
            ConsumerChannel[] reached) {
    }

    /** @return {@code targets} without those in {@code reached} (by identity); {@code targets} itself if none */
    static ConsumerChannel[] without(ConsumerChannel[] targets, ConsumerChannel[] reached) {
        if (reached == null || reached.length == 0 || targets.length == 0) {
            return targets;
        }
        List<ConsumerChannel> left = new ArrayList<>(targets.length);
        for (ConsumerChannel t : targets) {
            if (!Arrays.asList(reached).contains(t)) {
                left.add(t);
            }
        }
        return left.size() == targets.length ? targets : left.toArray(new ConsumerChannel[0]);
    }

    private final ArrayDeque<Held> queue = new ArrayDeque<>();

    int size() {
        return queue.size();
    }

    void append(Held held) {
        queue.addLast(held);
        held.counters.held.increment();
    }

    /**
     * Move every held event that {@code targets} now routes into those behaviours' queues, in hold order, beyond
     * their capacity if need be (the hold's bound limits that); the others stay held, in order.
     *
     * @return whether a behaviour became ready to run (then the caller signals the pool, after its lock)
     */
    boolean handOver(Function<Held, ConsumerChannel[]> targets) {
        boolean madeReady = false;
        for (Iterator<Held> it = queue.iterator(); it.hasNext();) {
            Held held = it.next();
            ConsumerChannel[] to = targets.apply(held);
            if (to.length > 0) {
                it.remove();
                held.counters.held.decrement();
                madeReady |= enqueue(held, to);
            }
        }
        return madeReady;
    }

    /** Queue one event that leaves the hold (or is re-dispatched) for these behaviours, waiting for none. */
    static boolean enqueue(Held held, ConsumerChannel[] to) {
        List<String> names = held.remoteNames != null ? held.remoteNames
                : held.type != null ? List.copyOf(RouteTable.typeNames(held.type)) : null;
        Envelope envelope = new Envelope(held.snapshot, held.counters, to.length == 1, names, null, false, to);
        boolean madeReady = false;
        for (ConsumerChannel c : to) {
            c.forceReserve();
            madeReady |= c.enqueue(envelope);
        }
        return madeReady;
    }

    /**
     * Held events taken out of the hold, by the bus's own rules: to the behaviours that take them now, else to the
     * consumers of last resort where allowed, else counted as unhandled (and told to {@code unhandled}).
     *
     * @return whether a behaviour became ready to run
     */
    static boolean dispatch(List<Held> released, Function<Held, ConsumerChannel[]> targets,
            ConsumerChannel[] lastResort, Predicate<Held> lastResortAllowed, Consumer<EventTypeCounters> unhandled) {
        boolean madeReady = false;
        for (Held held : released) {
            ConsumerChannel[] to = targets.apply(held);
            if (to.length == 0 && lastResortAllowed.test(held)) {
                to = lastResort;
            }
            if (to.length > 0) {
                madeReady |= enqueue(held, to);
            } else {
                held.counters.unhandled.increment();
                unhandled.accept(held.counters);
            }
        }
        return madeReady;
    }

    /** Those of {@code candidates} still held, in hold order. */
    List<Held> stillHeld(List<Held> candidates) {
        if (candidates.isEmpty()) {
            return List.of();
        }
        Set<Held> wanted = identities(candidates);
        return queue.stream().filter(wanted::contains).toList();
    }

    /** Take those of {@code candidates} still held that match out of the hold, in hold order. */
    List<Held> take(List<Held> candidates, Predicate<Held> which) {
        Set<Held> among = identities(candidates);
        return take(held -> among.contains(held) && which.test(held));
    }

    private static Set<Held> identities(List<Held> events) {
        Set<Held> set = Collections.newSetFromMap(new IdentityHashMap<>());
        set.addAll(events);
        return set;
    }

    /** Take the held events that match out of the hold, in hold order. */
    List<Held> take(Predicate<Held> which) {
        List<Held> removed = new ArrayList<>();
        for (Iterator<Held> it = queue.iterator(); it.hasNext();) {
            Held held = it.next();
            if (which.test(held)) {
                it.remove();
                held.counters.held.decrement();
                removed.add(held);
            }
        }
        return removed;
    }

    /** Take the held events of one type out of the hold. */
    List<Held> remove(String eventType) {
        return take(held -> held.counters.eventType.equals(eventType));
    }

    /** Take every held event out of the hold, in hold order. */
    List<Held> removeAll() {
        List<Held> removed = new ArrayList<>(queue);
        queue.clear();
        removed.forEach(h -> h.counters.held.decrement());
        return removed;
    }

    /** One entry per type, ordered by its oldest held event. */
    List<HeldType> types() {
        Map<String, HeldType> byType = new LinkedHashMap<>();
        for (Held held : queue) {
            HeldType t = byType.computeIfAbsent(held.counters.eventType, name -> {
                HeldType n = new HeldType();
                n.eventType = name;
                n.since = held.since;
                return n;
            });
            t.count++;
        }
        return new ArrayList<>(byType.values());
    }
}
