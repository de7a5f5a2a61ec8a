package eu.brain.iot.benchmarks.spi;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.CountDownLatch;

/**
 * Counts what one consumer receives and, when asked, records each event's latency.
 * <p>
 * Ownership: {@link #arm} is called by the publishing thread while no event is in flight; {@link #onEvent} only by
 * the bus thread that delivers to this consumer. Each of the measured buses calls one consumer one event at a time
 * (all promise per-consumer publish order), and hands events from the publisher to the delivering thread through
 * a concurrent queue, so the armed state is visible to it. A bus that called one consumer concurrently would lose
 * counts and the round would fail on its deadline rather than report a figure.
 */
public final class ConsumerProbe {

    private static final VarHandle SLOTS = MethodHandles.arrayElementVarHandle(long[].class);
    /** The counter sits in the middle of its own 16-slot array: no other probe's counter shares its cache line. */
    private static final int COUNT = 8;

    private final long[] count = new long[16];
    private long target;
    private CountDownLatch done;
    private long[] latencies;

    /**
     * Prepare a round: the count restarts at 0 and {@code done} is counted down once when it reaches {@code target}.
     *
     * @param latencies where to record each event's latency in nanoseconds, or {@code null} not to read the clock
     */
    public void arm(long target, CountDownLatch done, long[] latencies) {
        this.target = target;
        this.done = done;
        this.latencies = latencies;
        SLOTS.setRelease(count, COUNT, 0L);
    }

    /** Called by the consumer for every event, with the publish time the event carries. */
    public void onEvent(long sentNanos) {
        long n = (long) SLOTS.getOpaque(count, COUNT) + 1;
        long[] samples = latencies;
        if (samples != null && n <= samples.length) {
            samples[(int) (n - 1)] = System.nanoTime() - sentNanos;
        }
        SLOTS.setRelease(count, COUNT, n);
        if (n == target) {
            done.countDown();
        }
    }

    /** @return the events counted since the last {@link #arm} */
    public long received() {
        return (long) SLOTS.getAcquire(count, COUNT);
    }
}
