package eu.brain.iot.benchmarks.spi;

import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What the probe behaviour (installed on demand by the BMS and the BIS) reports from inside its {@code notify()}: the
 * first event's latency (its publish {@code nanoTime} to now), how many events arrived, and whether each publisher's
 * events arrived once and in order. Registered as a service by the launcher through the system bundle, whose package
 * the probe bundle imports.
 * <p>
 * Ownership: {@link #arm} is called by the launcher while no event is in flight; {@link #onEvent} by the bus's
 * delivery thread of the one probe behaviour (one call at a time); the fields it writes are read after {@link #done}.
 */
public final class InstallProbe {

    private volatile long firstLatencyNanos;
    private volatile long lastArrivalNanos;
    private final AtomicLong received = new AtomicLong();
    private final ConcurrentHashMap<String, Integer> nextSeq = new ConcurrentHashMap<>();
    private volatile long outOfOrder;
    private volatile long target;
    private volatile CountDownLatch done = new CountDownLatch(1);

    /** Expect {@code events} events from now on. */
    public void arm(long events) {
        firstLatencyNanos = -1;
        received.set(0);
        nextSeq.clear();
        outOfOrder = 0;
        target = events;
        done = new CountDownLatch(1);
    }

    /** Called inside the behaviour's {@code notify()} for every event. */
    public void onEvent(String publisher, int seq, long sentNanos) {
        long now = System.nanoTime();
        if (firstLatencyNanos < 0) {
            firstLatencyNanos = now - sentNanos;
        }
        int expected = nextSeq.getOrDefault(publisher, 0);
        if (seq != expected) {
            outOfOrder++;
        }
        nextSeq.put(publisher, seq + 1);
        lastArrivalNanos = now;
        if (received.incrementAndGet() == target) {
            done.countDown();
        }
    }

    public CountDownLatch done() {
        return done;
    }

    public long firstLatencyNanos() {
        return firstLatencyNanos;
    }

    public long lastArrivalNanos() {
        return lastArrivalNanos;
    }

    public long received() {
        return received.get();
    }

    /** @return events that came out of their publisher's order, or twice */
    public long outOfOrder() {
        return outOfOrder;
    }
}
