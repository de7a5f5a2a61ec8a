package eu.brain.iot.federation.impl;

import java.io.ByteArrayOutputStream;
import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;

import eu.brain.iot.federation.impl.Wire.MalformedException;

/**
 * Batches of events of {@value #MIN_BYTES} bytes or more travel deflated (zlib, RFC 1950, at the fastest level).
 * <p>
 * Why: Paho's receiver copies every byte of a message twice through single-byte reads (about 65 ns a byte here),
 * which made it the receiving node's busiest code; deflating costs about 2 ns a byte, inflating 1, and a batch of
 * events shrinks ten times or more. A zlib stream starts with 0x78 at this window size, which no JSON text does,
 * so a receiver tells a deflated batch from a plain one by its first byte. The signature covers the bytes on the
 * wire: a receiver verifies a batch before it inflates it, and inflates at most {@value #MAX_INFLATED_BYTES} bytes.
 * <p>
 * Threads: {@link #deflate} is called by the fabric's sender thread, {@link #inflateIfDeflated} by its inbound
 * thread; each keeps its (de)compressor under a lock of its own, so either may also be called from elsewhere.
 */
final class Compression {

    /** Smallest batch that is deflated: below it the saving does not pay for the work. */
    static final int MIN_BYTES = 1024;
    /** Largest batch a receiver inflates (the largest MQTT packet a node accepts). */
    static final int MAX_INFLATED_BYTES = (int) MqttLink.MAX_PACKET_BYTES;
    /** zlib's first byte for deflate with a 32 KB window, the only form {@link #deflate} writes. */
    private static final int ZLIB_CMF = 0x78;
    private static final int CHUNK = 64 * 1024;

    private final Object deflating = new Object();
    private final Object inflating = new Object();
    private final Deflater deflater = new Deflater(Deflater.BEST_SPEED);
    private final Inflater inflater = new Inflater();
    private final byte[] deflateChunk = new byte[CHUNK];
    private final byte[] inflateChunk = new byte[CHUNK];

    /** Whether a payload is a zlib stream (see the class comment) rather than JSON text. */
    static boolean isDeflated(byte[] payload) {
        return payload.length >= 2 && (payload[0] & 0xff) == ZLIB_CMF
                && (((payload[0] & 0xff) << 8) | (payload[1] & 0xff)) % 31 == 0;
    }

    /** {@code json} deflated when it is {@value #MIN_BYTES} bytes or more, else {@code json} itself. */
    byte[] deflateIfLarge(byte[] json) {
        return json.length < MIN_BYTES ? json : deflate(json);
    }

    byte[] deflate(byte[] data) {
        synchronized (deflating) {
            deflater.reset();
            deflater.setInput(data);
            deflater.finish();
            ByteArrayOutputStream out = new ByteArrayOutputStream(Math.max(64, data.length / 4));
            while (!deflater.finished()) {
                int n = deflater.deflate(deflateChunk);
                out.write(deflateChunk, 0, n);
            }
            return out.toByteArray();
        }
    }

    /**
     * The payload inflated if it is deflated, else the payload itself.
     *
     * @throws MalformedException if it is not a complete zlib stream, or inflates to more than
     *             {@value #MAX_INFLATED_BYTES} bytes
     */
    byte[] inflateIfDeflated(byte[] payload) throws MalformedException {
        if (!isDeflated(payload)) {
            return payload;
        }
        synchronized (inflating) {
            inflater.reset();
            inflater.setInput(payload);
            ByteArrayOutputStream out = new ByteArrayOutputStream(Math.min(payload.length * 8, 1 << 20));
            try {
                while (!inflater.finished()) {
                    int n = inflater.inflate(inflateChunk);
                    if (n == 0 && (inflater.needsInput() || inflater.needsDictionary())) {
                        throw new MalformedException("a deflated batch ends before its stream does");
                    }
                    if (out.size() + n > MAX_INFLATED_BYTES) {
                        throw new MalformedException("a deflated batch inflates to more than " + MAX_INFLATED_BYTES
                                + " bytes");
                    }
                    out.write(inflateChunk, 0, n);
                }
            } catch (DataFormatException e) {
                throw new MalformedException("a deflated batch is not a zlib stream: " + e.getMessage());
            }
            return out.toByteArray();
        }
    }
}
