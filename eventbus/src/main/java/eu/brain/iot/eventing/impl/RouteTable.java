package eu.brain.iot.eventing.impl;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;

/**
 * Which behaviours take which event types, for one fixed set of behaviours. A new table replaces the old one
 * whenever a behaviour comes or goes, so a table never changes; only its cache of computed routes grows.
 * Routes are cached by type name and remember their class weakly, so a table never keeps an uninstalled
 * bundle's classes alive. Cached routes hold their bus's counters, so a table, even an empty one, belongs to
 * one bus and is never shared between buses.
 */
final class RouteTable {

    private final List<ConsumerChannel> typedOrNamed;
    final ConsumerChannel[] lastResort;
    private final ConcurrentHashMap<String, Route> byClass = new ConcurrentHashMap<>();
    private final ConcurrentHashMap<String, Route> byName = new ConcurrentHashMap<>();
    private final ConcurrentHashMap<String, Route> byRemoteName = new ConcurrentHashMap<>();

    RouteTable(Collection<ConsumerChannel> channels) {
        List<ConsumerChannel> named = new ArrayList<>();
        List<ConsumerChannel> last = new ArrayList<>();
        for (ConsumerChannel c : channels) {
            (c.spec.lastResort() ? last : named).add(c);
        }
        this.typedOrNamed = List.copyOf(named);
        this.lastResort = last.toArray(ConsumerChannel[]::new);
    }

    /** The route of a typed event of this class (its supertypes' consumers included). */
    Route routeFor(Class<?> eventClass, Function<String, EventTypeCounters> counters) {
        Route route = byClass.get(eventClass.getName());
        if (route == null || route.type.get() != eventClass) {
            route = compute(typeNames(eventClass), counters.apply(eventClass.getName()), eventClass, false);
            byClass.put(eventClass.getName(), route);
        }
        return route;
    }

    /** The route of an untyped event: behaviours that consume exactly this type name. */
    Route routeFor(String eventType, Function<String, EventTypeCounters> counters) {
        return byName.computeIfAbsent(eventType,
                t -> compute(new LinkedHashSet<>(List.of(t)), counters.apply(t), null, false));
    }

    /**
     * The route of an event from another node: the local behaviours that consume any of {@code typeNames} (its
     * type, then its supertypes and interfaces), never a forwarder. Cached by the type name: a type's hierarchy is
     * the same whoever publishes it.
     */
    Route routeForRemote(String eventType, List<String> typeNames, Function<String, EventTypeCounters> counters) {
        return byRemoteName.computeIfAbsent(eventType,
                t -> compute(new LinkedHashSet<>(typeNames), counters.apply(t), null, true));
    }

    /**
     * The route of an event given up by a node that stayed offline: every consumer, forwarders included, of any of
     * {@code typeNames}. Not cached: rare.
     */
    Route routeForGivenUp(String eventType, List<String> typeNames, Function<String, EventTypeCounters> counters) {
        return compute(new LinkedHashSet<>(typeNames), counters.apply(eventType), null, false);
    }

    private Route compute(Set<String> names, EventTypeCounters counters, Class<?> type, boolean remote) {
        List<ConsumerChannel> plain = new ArrayList<>();
        List<ConsumerChannel> filtered = new ArrayList<>();
        Set<String> destinations = new HashSet<>();
        boolean forwarders = false;
        for (ConsumerChannel c : typedOrNamed) {
            if (remote && c.spec.forwarder()) {
                continue;
            }
            if (c.spec.consumed().stream().anyMatch(names::contains)) {
                if (c.spec.filter() != null) {
                    filtered.add(c);
                    forwarders |= c.spec.forwarder();
                } else if (!c.spec.forwarder() || destinations.add(c.spec.forwardTo())) {
                    plain.add(c); // one unfiltered forwarder per destination: a node receives each event once
                }
            }
        }
        return new Route(new WeakReference<>(type), counters, plain.toArray(ConsumerChannel[]::new),
                filtered.toArray(ConsumerChannel[]::new), List.copyOf(names), forwarders);
    }

    /** The names an event from another node is routed by: its type first, then the others given, without repeats. */
    static List<String> remoteNames(String eventType, List<String> typeNames) {
        Set<String> names = new LinkedHashSet<>();
        names.add(eventType);
        if (typeNames != null) {
            typeNames.stream().filter(n -> n != null && !n.isEmpty()).forEach(names::add);
        }
        return List.copyOf(names);
    }

    /** The names of the class, its superclasses and all its interfaces. */
    static Set<String> typeNames(Class<?> type) {
        Set<String> names = new LinkedHashSet<>();
        for (Class<?> c = type; c != null && c != Object.class; c = c.getSuperclass()) {
            names.add(c.getName());
            addInterfaces(c, names);
        }
        return names;
    }

    private static void addInterfaces(Class<?> type, Set<String> names) {
        for (Class<?> i : type.getInterfaces()) {
            if (names.add(i.getName())) {
                addInterfaces(i, names);
            }
        }
    }

    /**
     * The behaviours an event type goes to: those without a filter always, those with a filter when it matches;
     * {@code typeNames} is the type, then its supertypes and interfaces (what an unhandled-event policy is told).
     */
    record Route(WeakReference<Class<?>> type, EventTypeCounters counters, ConsumerChannel[] plain,
            ConsumerChannel[] filtered, List<String> typeNames, boolean filteredForwarders) {

        /**
         * The behaviours one event goes to: the unfiltered ones, and the filtered ones that match its fields.
         *
         * @param snapshot the bus's snapshot: an event object, or a map for an untyped event
         */
        ConsumerChannel[] targets(Object snapshot) {
            if (filtered.length == 0) {
                return plain;
            }
            @SuppressWarnings("unchecked")
            Map<String, ?> fields = snapshot instanceof Map<?, ?> map ? (Map<String, ?>) map
                    : EventMaps.toMap(snapshot);
            List<ConsumerChannel> matching = new ArrayList<>(Arrays.asList(plain));
            for (ConsumerChannel c : filtered) {
                if (c.spec.filter().matches(fields) && !(filteredForwarders && c.spec.forwarder()
                        && forwardsAlready(matching, c.spec.forwardTo()))) {
                    matching.add(c);
                }
            }
            return matching.toArray(ConsumerChannel[]::new);
        }

        /** Whether a forwarder to this destination is among the targets already (one copy per node). */
        private static boolean forwardsAlready(List<ConsumerChannel> targets, String destination) {
            for (ConsumerChannel t : targets) {
                if (destination.equals(t.spec.forwardTo())) {
                    return true;
                }
            }
            return false;
        }
    }
}
