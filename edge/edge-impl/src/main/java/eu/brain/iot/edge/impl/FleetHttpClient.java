package eu.brain.iot.edge.impl;

import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.URI;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import io.netty.bootstrap.Bootstrap;
import io.netty.buffer.Unpooled;
import io.netty.channel.Channel;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.nio.NioEventLoopGroup;
import io.netty.channel.pool.AbstractChannelPoolHandler;
import io.netty.channel.pool.AbstractChannelPoolMap;
import io.netty.channel.pool.ChannelHealthChecker;
import io.netty.channel.pool.FixedChannelPool;
import io.netty.channel.socket.nio.NioSocketChannel;
import io.netty.handler.codec.http.DefaultFullHttpRequest;
import io.netty.handler.codec.http.FullHttpRequest;
import io.netty.handler.codec.http.HttpClientCodec;
import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpHeaderValues;
import io.netty.handler.codec.http.HttpMethod;
import io.netty.handler.codec.http.HttpObjectAggregator;
import io.netty.handler.codec.http.HttpVersion;
import io.netty.util.concurrent.DefaultThreadFactory;
import io.netty.util.concurrent.Future;

/**
 * The edge's HTTP/1.1 client: asynchronous (Netty), keep-alive connections pooled per host, at most
 * {@code maxConnections} requests in flight per host (more wait for a connection, up to the timeout), every
 * request bounded by the timeout. No thread per device: {@code ioThreads} threads serve every connection.
 * <p>
 * One request at a time per connection (no pipelining: a device may answer pipelined requests out of order).
 * A connection whose request timed out or failed is closed, never reused: a late answer could otherwise be taken
 * for the next request's.
 */
final class FleetHttpClient implements AutoCloseable {

    /** Bodies are small JSON documents; a larger answer is a broken device, not data. */
    private static final int MAX_ANSWER_BYTES = 1 << 20;

    private final EventLoopGroup group;
    private final AbstractChannelPoolMap<InetSocketAddress, FixedChannelPool> pools;
    /** The request header by which the edge names its node on every command: robot-sim records who drove a robot. */
    static final String NODE_HEADER = "X-Brain-Node";

    private final long timeoutMillis;
    private final String nodeName;

    FleetHttpClient(int ioThreads, int maxConnections, long timeoutMillis) {
        this(ioThreads, maxConnections, timeoutMillis, EdgeNode.DEFAULT_NAME);
    }

    /**
     * @param nodeName the node's name, sent in {@value #NODE_HEADER} with every command (POST), and in the I/O
     *                 threads' names ({@code edge-http-<node>-...})
     */
    FleetHttpClient(int ioThreads, int maxConnections, long timeoutMillis, String nodeName) {
        this.timeoutMillis = timeoutMillis;
        this.nodeName = nodeName;
        this.group = new NioEventLoopGroup(ioThreads, new DefaultThreadFactory("edge-http-" + nodeName, true));
        Bootstrap bootstrap = new Bootstrap().group(group).channel(NioSocketChannel.class)
                .option(ChannelOption.TCP_NODELAY, true)
                .option(ChannelOption.SO_KEEPALIVE, true)
                .option(ChannelOption.CONNECT_TIMEOUT_MILLIS, (int) Math.min(Integer.MAX_VALUE, timeoutMillis));
        this.pools = new AbstractChannelPoolMap<>() {
            @Override
            protected FixedChannelPool newPool(InetSocketAddress host) {
                return new FixedChannelPool(bootstrap.clone().remoteAddress(host), new PipelineSetUp(),
                        ChannelHealthChecker.ACTIVE, FixedChannelPool.AcquireTimeoutAction.FAIL, timeoutMillis,
                        maxConnections, Integer.MAX_VALUE, true, true);
            }
        };
    }

    CompletableFuture<HttpAnswer> get(URI uri) {
        return send(HttpMethod.GET, uri, null);
    }

    CompletableFuture<HttpAnswer> post(URI uri, byte[] json) {
        return send(HttpMethod.POST, uri, json);
    }

    private CompletableFuture<HttpAnswer> send(HttpMethod method, URI uri, byte[] json) {
        CompletableFuture<HttpAnswer> answer = new CompletableFuture<>();
        InetSocketAddress host = InetSocketAddress.createUnresolved(uri.getHost(), port(uri));
        if (group.isShuttingDown()) {
            // Netty would reject the acquire's listener, log an ERROR with its stack trace and never answer
            answer.completeExceptionally(new DeviceIOException("the edge's HTTP client is closed"));
            return answer;
        }
        FixedChannelPool pool;
        try {
            pool = pools.get(host);
        } catch (IllegalStateException closed) {
            answer.completeExceptionally(new DeviceIOException("the edge's HTTP client is closed"));
            return answer;
        }
        pool.acquire().addListener((Future<Channel> acquired) -> {
            if (!acquired.isSuccess()) {
                answer.completeExceptionally(new DeviceIOException(describe(acquired.cause(), uri),
                        acquired.cause() instanceof java.util.concurrent.TimeoutException));
                return;
            }
            Channel channel = acquired.getNow();
            InFlightRequest inFlight = new InFlightRequest(answer, pool, channel, uri);
            channel.attr(InFlightRequest.KEY).set(inFlight);
            inFlight.timeout = channel.eventLoop().schedule(
                    () -> inFlight.fail("no answer within " + timeoutMillis + " ms"), timeoutMillis,
                    TimeUnit.MILLISECONDS);
            FullHttpRequest request = request(method, uri, json);
            inFlight.sentNanos = System.nanoTime();
            channel.writeAndFlush(request).addListener(written -> {
                if (!written.isSuccess()) {
                    inFlight.fail("could not send the request: " + written.cause());
                }
            });
        });
        return answer;
    }

    private FullHttpRequest request(HttpMethod method, URI uri, byte[] json) {
        String target = uri.getRawPath() + (uri.getRawQuery() == null ? "" : "?" + uri.getRawQuery());
        FullHttpRequest request = json == null
                ? new DefaultFullHttpRequest(HttpVersion.HTTP_1_1, method, target, Unpooled.EMPTY_BUFFER)
                : new DefaultFullHttpRequest(HttpVersion.HTTP_1_1, method, target, Unpooled.wrappedBuffer(json));
        request.headers().set(HttpHeaderNames.HOST, uri.getHost() + ":" + port(uri))
                .set(HttpHeaderNames.ACCEPT, HttpHeaderValues.APPLICATION_JSON)
                .setInt(HttpHeaderNames.CONTENT_LENGTH, json == null ? 0 : json.length);
        if (json != null) {
            request.headers().set(HttpHeaderNames.CONTENT_TYPE, HttpHeaderValues.APPLICATION_JSON)
                    .set(NODE_HEADER, nodeName);
        }
        return request;
    }

    private static int port(URI uri) {
        return uri.getPort() == -1 ? 80 : uri.getPort();
    }

    private String describe(Throwable cause, URI uri) {
        if (cause instanceof ConnectException || (cause != null && cause.getCause() instanceof ConnectException)) {
            return "cannot connect to " + uri.getHost() + ":" + port(uri) + " (" + cause.getMessage() + ")";
        }
        if (cause instanceof java.util.concurrent.TimeoutException) {
            return "no free connection to " + uri.getHost() + ":" + port(uri) + " within " + timeoutMillis
                    + " ms (every connection busy)";
        }
        return "cannot reach " + uri.getHost() + ":" + port(uri) + ": " + cause;
    }

    /** Whether {@link #close} finished stopping the I/O threads. */
    boolean terminated() {
        return group.isTerminated();
    }

    @Override
    public void close() {
        pools.close();
        group.shutdownGracefully(0, 1, TimeUnit.SECONDS);
    }

    /** Sets up a new connection's pipeline. */
    private static final class PipelineSetUp extends AbstractChannelPoolHandler {
        @Override
        public void channelCreated(Channel channel) {
            channel.pipeline().addLast(new HttpClientCodec(), new HttpObjectAggregator(MAX_ANSWER_BYTES),
                    new AnswerHandler());
        }
    }
}
