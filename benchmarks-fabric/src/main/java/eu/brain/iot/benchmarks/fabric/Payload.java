package eu.brain.iot.benchmarks.fabric;

import java.nio.ByteBuffer;

/**
 * A benchmark message: its sequence number and the publisher's {@code System.nanoTime()} just before it was handed
 * to the client, then padding up to {@link #SIZE} bytes (about the size of a small fabric event on the wire).
 * {@code System.nanoTime()} reads CLOCK_MONOTONIC on Linux, the same clock in every process of a machine, so the
 * subscriber's process can subtract it from its own reading.
 */
final class Payload {
    static final int SIZE = 120;

    private Payload() {
    }

    static byte[] encode(long sequence, long sentNanos) {
        return ByteBuffer.allocate(SIZE).putLong(sequence).putLong(sentNanos).array();
    }

    static long sequence(ByteBuffer payload) {
        return payload.getLong(0);
    }

    static long sentNanos(ByteBuffer payload) {
        return payload.getLong(Long.BYTES);
    }
}
