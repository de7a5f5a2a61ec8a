package eu.brain.iot.behaviours.robot.impl;

import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/**
 * The rule that makes one robot behaviour instance of a fabric drive the whole fleet: one errand table (a cart is
 * claimed once fleet-wide) and one traffic planner's reservation table. Every instance hears every other's
 * {@link RobotBehaviourAlive}; the instances heard within {@link #aliveMillis} are alive, and the one that started
 * first (then the lowest instance id) leads. An instance on a node that has the whole fleet leads at once; on a
 * fleet shared between nodes it first listens for {@link #LISTEN_PERIODS} alive periods, so that an instance
 * starting beside one that already drives the fleet never drives it too: the other's beats reach it only once its
 * own interest in them has crossed the fabric, which one alive period did not always cover. Having heard another
 * instance it still listens for one alive period from its start: instances that start together hear each other at
 * different times (each one's interest crosses the fabric to each other node on its own), and one that had heard
 * only younger ones would drive the fleet beside the eldest until the eldest's beats reached it. When the leader stops
 * beating (its node died), the next one leads after {@link #aliveMillis}, and takes the robots over as a behaviour
 * started again does; when it says it leaves ({@link #left}: its bundle stopped), at once. An instance that left is
 * not heard again: a beat it sent before it left may reach a listener after its farewell, or after the instance that
 * replaces it on the same node started, which would otherwise stand by for an alive period behind a dead leader.
 * <p>
 * Not thread-safe: its owner ({@link FleetLeadership}) calls it under its lock.
 */
final class Leadership {

    /** An instance, as its beats say. */
    record Instance(String node, String id, long startedMillis) {
    }

    private static final Comparator<Instance> ELDEST = Comparator.comparingLong(Instance::startedMillis)
            .thenComparing(Instance::id);

    /** Alive periods a new instance on a shared fleet listens before it leads when it hears nobody. */
    static final int LISTEN_PERIODS = 3;
    /** Instances that left remembered, the latest ones (an instance id is new at each start). */
    static final int LEFT_REMEMBERED = 64;

    private final Instance self;
    private final long aliveMillis;
    private final long startedNanos;
    /** Whether another instance was ever heard (its listening then ends one alive period after its start). */
    private boolean heardAny;
    /** The other instances and when each was last heard (nanos). */
    private final Map<String, Heard> others = new HashMap<>();
    /** The ids of the instances that said they left, oldest first, at most {@link #LEFT_REMEMBERED}. */
    private final Set<String> left = new LinkedHashSet<>();

    private record Heard(Instance instance, long atNanos) {
    }

    Leadership(Instance self, long aliveMillis, long nowNanos) {
        this.self = self;
        this.aliveMillis = aliveMillis;
        this.startedNanos = nowNanos;
    }

    Instance self() {
        return self;
    }

    void heard(Instance other, long nowNanos) {
        if (!other.id().equals(self.id()) && !left.contains(other.id())) {
            others.put(other.id(), new Heard(other, nowNanos));
            heardAny = true; // the fabric brings the others' beats here: one alive period of listening is enough
        }
    }

    /** The instance said it leaves: it is not alive any more, whatever beat of it comes later. */
    void left(Instance other) {
        if (other.id().equals(self.id())) {
            return;
        }
        others.remove(other.id());
        left.add(other.id());
        if (left.size() > LEFT_REMEMBERED) {
            left.remove(left.iterator().next());
        }
    }

    /**
     * @param wholeFleetHere whether this node has every device of the fleet (a node alone)
     * @return the instance that drives the fleet now, as this one sees it
     */
    Instance leader(boolean wholeFleetHere, long nowNanos) {
        long window = aliveMillis * 1_000_000L;
        others.values().removeIf(h -> nowNanos - h.atNanos() > window);
        Instance best = self;
        for (Heard h : others.values()) {
            if (ELDEST.compare(h.instance(), best) < 0) {
                best = h.instance();
            }
        }
        boolean listening = nowNanos - startedNanos < (heardAny ? 1 : LISTEN_PERIODS) * window;
        if (best == self && !wholeFleetHere && listening) {
            return null; // still listening for an instance that drives the fleet already, or one that started earlier
        }
        return best;
    }
}
