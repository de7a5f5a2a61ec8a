package eu.brain.iot.bis.impl.repo;

import java.net.URI;

/**
 * One read in progress, for people asking what the installer is doing: its URL, how many bytes it expects (or -1),
 * how many arrived, since when. Written by the reading thread, read by any: every field is volatile or final.
 */
public final class Transfer {

    private final URI url;
    private final long expected;
    private final long startedAt = System.currentTimeMillis();
    private volatile java.util.function.LongSupplier received = () -> 0;

    public Transfer(URI url, long expected) {
        this.url = url;
        this.expected = expected;
    }

    void receivedBy(java.util.function.LongSupplier counter) {
        this.received = counter;
    }

    public URI url() {
        return url;
    }

    /** e.g. {@code http://host/b.jar: 1200 of 45000 bytes after 12 s} */
    public String describe() {
        long seconds = (System.currentTimeMillis() - startedAt) / 1000;
        return url + ": " + received.getAsLong() + (expected >= 0 ? " of " + expected : "") + " bytes after "
                + seconds + " s";
    }
}
