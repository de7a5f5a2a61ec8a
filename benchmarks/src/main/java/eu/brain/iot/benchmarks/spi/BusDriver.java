package eu.brain.iot.benchmarks.spi;

/**
 * What the benchmark asks of one bus. A driver bundle implements it inside the embedded framework, with the bus's
 * own API and event type, and registers it as a service; the launcher sees only this interface, which the
 * framework's system bundle exports (system packages extra), so no bus class ever crosses into the launcher.
 * <p>
 * The publishing loops live in the driver bundle on purpose: every contender then gets its own copy of the loop,
 * JIT-compiled against its own bus alone.
 */
public interface BusDriver {

    /**
     * Register one consumer per probe, each as a whiteboard service of the bus, delivering every event of the
     * benchmark type to its probe's {@link ConsumerProbe#onEvent(long)}.
     *
     * @return unregisters the consumers
     */
    AutoCloseable registerConsumers(ConsumerProbe[] probes);

    /** Publish {@code count} events back to back from the calling thread. */
    void publishBurst(int count);

    /**
     * Publish {@code count} events from the calling thread, one every {@code intervalNanos}; each carries the
     * {@link System#nanoTime()} read just before it is handed to the bus.
     */
    void publishPaced(int count, long intervalNanos);
}
