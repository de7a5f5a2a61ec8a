package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;

import org.osgi.service.log.Logger;

import com.fasterxml.jackson.core.JsonProcessingException;

import eu.brain.iot.edge.model.api.DeviceModel.Subscription;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceValue;
import jakarta.servlet.AsyncContext;
import jakarta.servlet.AsyncEvent;
import jakarta.servlet.AsyncListener;
import jakarta.servlet.ServletOutputStream;
import jakarta.servlet.WriteListener;

/**
 * One SSE client: a bounded queue between the edge and the client's connection, written with non-blocking servlet
 * output.
 * <p>
 * Threads: {@link #changed} runs on the edge's fleet thread and only offers to the queue (it never waits); when the
 * queue is full the client is too slow and is disconnected, so one slow client costs the edge nothing. Writing
 * happens on the shared SSE thread ({@code writer}) or on a container thread ({@link #onWritePossible}), under this
 * object's lock; writes never block (the output is in non-blocking mode), so neither thread waits on a client.
 * Heartbeat comments go through the same queue; a write to a client that went away fails, which ends the stream and
 * its subscription; a client that stays connected but reads nothing is ended by {@link #checkStalled} (writer thread).
 */
final class SseClient implements ResourceListener, WriteListener, AsyncListener {

    private static final String HEARTBEAT = ": heartbeat\n\n";

    private final AsyncContext async;
    private final ServletOutputStream out;
    private final Executor writer;
    private final BlockingQueue<String> queue;
    private final int capacity;
    private final long writeTimeoutMillis;
    /** When the connection last stopped taking bytes (System.nanoTime), or 0 while it takes them. */
    private volatile long stalledSince;
    private final String who;
    private final Logger log;
    private final Consumer<SseClient> onClose;
    private final AtomicBoolean drainQueued = new AtomicBoolean();
    private final AtomicBoolean closed = new AtomicBoolean();
    private volatile Subscription subscription;
    /** Guarded by {@code this}: bytes written since the last flush. */
    private boolean unflushed;

    SseClient(AsyncContext async, Executor writer, int capacity, long writeTimeoutMillis, String who, Logger log,
            Consumer<SseClient> onClose) throws IOException {
        this.async = async;
        this.out = async.getResponse().getOutputStream();
        this.writer = writer;
        this.capacity = capacity;
        this.writeTimeoutMillis = writeTimeoutMillis;
        this.queue = new ArrayBlockingQueue<>(capacity);
        this.who = who;
        this.log = log;
        this.onClose = onClose;
    }

    /** Starts writing (the first bytes send the headers) and takes the subscription that feeds this client. */
    void start(String greeting, java.util.function.Function<ResourceListener, Subscription> subscribe) {
        async.addListener(this);
        queue.offer(": " + greeting + "\n\n");
        out.setWriteListener(this); // the container calls onWritePossible at once
        Subscription s = subscribe.apply(this);
        subscription = s;
        if (closed.get()) {
            s.close(); // closed while subscribing
        }
    }

    @Override
    public void changed(ResourceValue value) {
        if (closed.get()) {
            return;
        }
        String frame;
        try {
            frame = "data: " + Replies.MAPPER.writeValueAsString(Views.resource(value)) + "\n\n";
        } catch (JsonProcessingException e) {
            log.warn("SSE: cannot write " + value + " as JSON: " + e.getOriginalMessage());
            return;
        }
        offer(frame);
    }

    void heartbeat() {
        offer(HEARTBEAT);
    }

    private void offer(String frame) {
        if (closed.get()) {
            return;
        }
        if (!queue.offer(frame)) {
            close("too slow: " + capacity + " changes waiting to be sent (sse.queue.capacity); it may reconnect", true);
            return;
        }
        if (drainQueued.compareAndSet(false, true)) {
            try {
                writer.execute(() -> {
                    drainQueued.set(false);
                    drain();
                });
            } catch (RejectedExecutionException e) {
                close("the edge's REST service is stopping", false);
            }
        }
    }

    /**
     * A client that stopped reading (the kernel's buffers full, so the container takes no more) is disconnected
     * once it has taken nothing for {@code sse.write.timeout.ms}; without this it would be found only when its
     * queue fills, which at a few changes a second takes minutes behind megabytes of socket buffers.
     */
    void checkStalled() {
        long since = stalledSince;
        if (since != 0 && System.nanoTime() - since > writeTimeoutMillis * 1_000_000) {
            close("not reading: it took no bytes for " + writeTimeoutMillis + " ms (sse.write.timeout.ms); "
                    + "it may reconnect", true);
        }
    }

    @Override
    public void onWritePossible() {
        stalledSince = 0;
        drain();
    }

    /** Writes what is queued while the connection takes it; when it does not, the container calls back later. */
    private synchronized void drain() {
        if (closed.get()) {
            return;
        }
        try {
            while (out.isReady()) {
                String next = queue.poll();
                if (next == null) {
                    if (!unflushed) {
                        return;
                    }
                    unflushed = false;
                    out.flush(); // SSE: each change must reach the client now, not when a buffer fills
                    continue;
                }
                out.write(next.getBytes(StandardCharsets.UTF_8));
                unflushed = true;
            }
            if (stalledSince == 0) {
                stalledSince = System.nanoTime(); // the container calls onWritePossible when it takes bytes again
            }
        } catch (IOException | IllegalStateException e) {
            close("it went away (a write failed: " + e.getMessage() + ")", false);
        }
    }

    @Override
    public void onError(Throwable t) {
        close("it went away (" + t + ")", false);
    }

    @Override
    public void onError(AsyncEvent event) {
        close("it went away (" + event.getThrowable() + ")", false);
    }

    @Override
    public void onComplete(AsyncEvent event) {
        close(null, false);
    }

    @Override
    public void onTimeout(AsyncEvent event) {
        close("timed out", false);
    }

    @Override
    public void onStartAsync(AsyncEvent event) {
        // not restarted
    }

    /** Ends the stream once: the subscription first (so the edge stops calling), then the response. */
    void close(String why, boolean warn) {
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        Subscription s = subscription;
        if (s != null) {
            s.close();
        }
        onClose.accept(this);
        queue.clear();
        if (why != null) {
            String message = "SSE client " + who + " disconnected at " + Instant.now() + ": " + why;
            if (warn) {
                log.warn(message);
            } else {
                log.info(message);
            }
        }
        // complete() off the caller's thread: the caller may be the edge's
        try {
            writer.execute(this::complete);
        } catch (RejectedExecutionException e) {
            complete();
        }
    }

    private void complete() {
        try {
            async.complete();
        } catch (IllegalStateException e) {
            // the container ended it already
        }
    }

    @Override
    public String toString() {
        return who;
    }
}
