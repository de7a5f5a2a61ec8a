package eu.brain.iot.dashboard;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.function.Consumer;

import jakarta.servlet.AsyncContext;
import jakarta.servlet.AsyncEvent;
import jakarta.servlet.AsyncListener;
import jakarta.servlet.ServletOutputStream;
import jakarta.servlet.WriteListener;

/**
 * One page's event stream: a bounded queue of SSE frames, written with non-blocking servlet output so that no
 * thread ever waits on a slow page.
 * <p>
 * Threads: {@link #send} is called by the dashboard's thread; {@link #onWritePossible} by a container thread when
 * the connection takes bytes again; both write under this object's lock and never block. A page that lets more than
 * {@code capacity} frames wait is disconnected: it reconnects by itself with its last event id and catches up.
 * {@code onClose} is called once, on whichever thread saw the end.
 */
final class SseStream implements WriteListener, AsyncListener {

    private final AsyncContext async;
    private final ServletOutputStream out;
    private final int capacity;
    private final Consumer<SseStream> onClose;
    /** Guarded by {@code this}. */
    private final ArrayDeque<String> queue = new ArrayDeque<>();
    /** Guarded by {@code this}. */
    private boolean unflushed;
    /** Guarded by {@code this}. */
    private boolean closed;

    SseStream(AsyncContext async, int capacity, Consumer<SseStream> onClose) throws IOException {
        this.async = async;
        this.out = async.getResponse().getOutputStream();
        this.capacity = capacity;
        this.onClose = onClose;
        async.addListener(this);
    }

    /** Starts writing; the container calls {@link #onWritePossible} at once. */
    void start() {
        out.setWriteListener(this);
    }

    /** Queues a frame and writes what the connection takes now. */
    void send(String frame) {
        boolean tooSlow;
        synchronized (this) {
            if (closed) {
                return;
            }
            tooSlow = queue.size() >= capacity;
            if (!tooSlow) {
                queue.addLast(frame);
            }
        }
        if (tooSlow) {
            close();
        } else {
            onWritePossible();
        }
    }

    @Override
    public synchronized void onWritePossible() {
        if (closed) {
            return;
        }
        try {
            while (out.isReady()) {
                String next = queue.pollFirst();
                if (next == null) {
                    if (!unflushed) {
                        return;
                    }
                    unflushed = false;
                    out.flush(); // each event must reach the page now, not when a buffer fills
                    continue;
                }
                out.write(next.getBytes(StandardCharsets.UTF_8));
                unflushed = true;
            }
        } catch (IOException | IllegalStateException e) {
            close();
        }
    }

    @Override
    public void onError(Throwable t) {
        close();
    }

    @Override
    public void onComplete(AsyncEvent event) {
        close();
    }

    @Override
    public void onTimeout(AsyncEvent event) {
        close();
    }

    @Override
    public void onError(AsyncEvent event) {
        close();
    }

    @Override
    public void onStartAsync(AsyncEvent event) {
        // never restarted
    }

    /** Ends the stream once. */
    void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            queue.clear();
        }
        onClose.accept(this);
        try {
            async.complete();
        } catch (IllegalStateException e) {
            // the container ended it already
        }
    }
}
