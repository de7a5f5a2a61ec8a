package eu.brain.iot.edge.impl;

import java.net.URI;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicBoolean;

import io.netty.buffer.ByteBufUtil;
import io.netty.channel.Channel;
import io.netty.channel.pool.ChannelPool;
import io.netty.handler.codec.http.FullHttpResponse;
import io.netty.handler.codec.http.HttpUtil;
import io.netty.util.AttributeKey;
import io.netty.util.concurrent.ScheduledFuture;

/**
 * One request on one pooled connection, from the write to the answer, the failure or the timeout, whichever
 * comes first ({@link #done} decides: they may race on different threads). Ends by giving the connection back
 * to the pool: open for the next request after a clean answer, closed after anything else.
 */
final class InFlightRequest {

    static final AttributeKey<InFlightRequest> KEY = AttributeKey.valueOf("eu.brain.iot.edge.request");

    private final CompletableFuture<HttpAnswer> answer;
    private final ChannelPool pool;
    private final Channel channel;
    private final URI uri;
    private final AtomicBoolean done = new AtomicBoolean();
    volatile ScheduledFuture<?> timeout;
    volatile long sentNanos;

    InFlightRequest(CompletableFuture<HttpAnswer> answer, ChannelPool pool, Channel channel, URI uri) {
        this.answer = answer;
        this.pool = pool;
        this.channel = channel;
        this.uri = uri;
    }

    void complete(FullHttpResponse response) {
        if (!response.decoderResult().isSuccess()) {
            fail("malformed HTTP answer: " + response.decoderResult().cause());
            return;
        }
        if (!done.compareAndSet(false, true)) {
            return;
        }
        cancelTimeout();
        byte[] body = ByteBufUtil.getBytes(response.content());
        boolean reusable = HttpUtil.isKeepAlive(response);
        channel.attr(KEY).set(null);
        if (!reusable) {
            channel.close();
        }
        pool.release(channel);
        answer.complete(new HttpAnswer(response.status().code(), body, sentNanos));
    }

    void fail(String reason) {
        if (!done.compareAndSet(false, true)) {
            return;
        }
        cancelTimeout();
        channel.attr(KEY).set(null);
        channel.close();
        pool.release(channel);
        answer.completeExceptionally(new DeviceIOException(reason + " (" + uri + ")"));
    }

    private void cancelTimeout() {
        ScheduledFuture<?> t = timeout;
        if (t != null) {
            t.cancel(false);
        }
    }
}
