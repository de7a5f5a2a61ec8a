package eu.brain.iot.edge.rest;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;

import jakarta.servlet.ReadListener;
import jakarta.servlet.ServletInputStream;

/**
 * Reads a request body with non-blocking servlet input, so that a client sending its body slowly holds a
 * connection but no container thread (a blocking read let ~200 such clients stop the whole API).
 * <p>
 * Threads: Jetty calls {@link #onDataAvailable} and {@link #onAllDataRead} on a container thread, one call at a
 * time; the body's deadline (see {@link Acts}) may give up from the timer thread, which only sets {@link #over}.
 * Exactly one of {@code done} and {@code failed} is called, at most once.
 */
final class BodyReader implements ReadListener {

    private final ServletInputStream in;
    private final int maxBytes;
    private final Consumer<byte[]> done;
    private final Consumer<HttpError> failed;
    private final ByteArrayOutputStream body = new ByteArrayOutputStream();
    private final byte[] chunk = new byte[4_096];
    private final AtomicBoolean over = new AtomicBoolean();

    BodyReader(ServletInputStream in, int maxBytes, Consumer<byte[]> done, Consumer<HttpError> failed) {
        this.in = in;
        this.maxBytes = maxBytes;
        this.done = done;
        this.failed = failed;
    }

    /** Starts reading: the container calls back as bytes arrive. */
    void start() {
        in.setReadListener(this);
    }

    /** Stops listening (the deadline passed): later bytes are ignored. @return whether reading was still going on */
    boolean abandon() {
        return over.compareAndSet(false, true);
    }

    @Override
    public void onDataAvailable() throws IOException {
        while (!over.get() && in.isReady() && !in.isFinished()) {
            int n = in.read(chunk);
            if (n < 0) {
                return;
            }
            body.write(chunk, 0, n);
            if (body.size() > maxBytes && over.compareAndSet(false, true)) {
                failed.accept(tooLarge(maxBytes));
                return;
            }
        }
    }

    @Override
    public void onAllDataRead() {
        if (over.compareAndSet(false, true)) {
            done.accept(body.toByteArray());
        }
    }

    @Override
    public void onError(Throwable t) {
        if (over.compareAndSet(false, true)) {
            // the client went away or broke the framing: the connection is over, the answer goes nowhere
            failed.accept(HttpError.closing(400, "body", "the request body could not be read: " + t));
        }
    }

    static HttpError tooLarge(int maxBytes) {
        return HttpError.closing(413, "body", "the body is larger than " + maxBytes + " bytes (act.max.body.bytes); "
                + "an ACT takes a small JSON object of parameters such as " + Acts.EXAMPLE);
    }
}
