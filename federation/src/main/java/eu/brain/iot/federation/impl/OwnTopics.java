package eu.brain.iot.federation.impl;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

/**
 * Keeps the broker's retained copy of this node's own {@code status} and {@code interest} genuine. Every node
 * subscribes to every node's retained topics, its own included, so it hears what another client publishes there: a
 * message this node did not sign (unsigned, signed with another key, or an empty one that removes the retained
 * message) would stand in for its own at the broker, and the nodes that start later would not see it. Such a message
 * is refused ({@link Refusals#refusedOwn}) and this node publishes its own current one again at once; a message it
 * signed itself (its own, or its own Last Will) is left alone.
 * <p>
 * A flood of such messages makes at most one publication per topic every {@link #MIN_REPUBLISH_MILLIS}: the ones
 * inside that time are answered together by one publication at its end.
 * <p>
 * Threads: the fabric's inbound thread only (its scheduled publications run on it too).
 */
final class OwnTopics {

    /** Least time between two publications of one topic made to replace a refused message. */
    static final long MIN_REPUBLISH_MILLIS = 1000;

    /** Publishes this node's current retained message of one kind ({@link Topics#STATUS}, {@link Topics#INTEREST}). */
    interface Republish {
        void publish(String kind);
    }

    private final FabricKey key;
    private final Refusals refusals;
    private final ScheduledExecutorService in;
    private final LongSupplier clock;
    private final Republish republish;
    /** By kind: when it was last published again; a kind is present in {@link #scheduled} while one waits. */
    private final Map<String, Long> lastRepublished = new HashMap<>();
    private final Set<String> scheduled = new HashSet<>();

    /** @param clock milliseconds since the epoch */
    OwnTopics(FabricKey key, Refusals refusals, ScheduledExecutorService in, LongSupplier clock,
            Republish republish) {
        this.key = key;
        this.refusals = refusals;
        this.in = in;
        this.clock = clock;
        this.republish = republish;
    }

    /** A message received on this node's own {@code kind} topic ({@link Topics#STATUS}, {@link Topics#INTEREST}). */
    void received(String topic, String kind, byte[] payload, String signature) {
        Refusals.Reason reason = Refusals.check(key, topic, payload, signature);
        if (reason == null) {
            return; // this node's own
        }
        refusals.refusedOwn(topic, reason);
        if (scheduled.contains(kind)) {
            return;
        }
        long wait = lastRepublished.getOrDefault(kind, Long.MIN_VALUE / 2) + MIN_REPUBLISH_MILLIS
                - clock.getAsLong();
        if (wait <= 0) {
            publish(kind);
        } else {
            scheduled.add(kind);
            in.schedule(() -> {
                scheduled.remove(kind);
                publish(kind);
            }, wait, TimeUnit.MILLISECONDS);
        }
    }

    private void publish(String kind) {
        lastRepublished.put(kind, clock.getAsLong());
        republish.publish(kind);
    }
}
