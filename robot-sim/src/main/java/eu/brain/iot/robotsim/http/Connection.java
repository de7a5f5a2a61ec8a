package eu.brain.iot.robotsim.http;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.CompositeByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelDuplexHandler;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.handler.codec.DecoderResult;
import io.netty.handler.codec.http.DefaultFullHttpResponse;
import io.netty.handler.codec.http.FullHttpResponse;
import io.netty.handler.codec.http.HttpContent;
import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpHeaderValues;
import io.netty.handler.codec.http.HttpMethod;
import io.netty.handler.codec.http.HttpRequest;
import io.netty.handler.codec.http.HttpResponseStatus;
import io.netty.handler.codec.http.HttpUtil;
import io.netty.handler.codec.http.HttpVersion;
import io.netty.handler.codec.http.LastHttpContent;
import io.netty.handler.codec.http.TooLongHttpHeaderException;
import io.netty.handler.codec.http.TooLongHttpLineException;
import io.netty.util.ReferenceCountUtil;
import io.netty.util.concurrent.ScheduledFuture;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.concurrent.TimeUnit;

/**
 * One client connection: reads one request at a time, answers it, and only then reads the next, so pipelined requests
 * are answered (and take effect) in request order. The channel does not read by itself (auto-read is off); a
 * {@code FlowControlHandler} ahead of this handler holds requests the decoder already took apart until asked. It also
 * gathers the body (at most {@code maxBody} bytes, else 413), refuses what the decoder could not read (400, 414, 431)
 * and a request that does not arrive whole within the request timeout once its first bytes came (408), every answer
 * the JSON error of robot-sim's API.
 * <p>
 * Threads: every field is owned by the channel's event loop. Answers computed elsewhere (the world thread) reach
 * {@link #answer} through the event loop (see {@link ServerExchange}).
 */
final class Connection extends ChannelDuplexHandler {
    private enum State { IDLE, READING, BUSY, CLOSING }

    private final Router router;
    private final RequestGate gate;
    private final int maxBody;
    private final long timeoutMillis;

    private State state = State.IDLE;
    private ChannelHandlerContext ctx;
    private HttpRequest head;
    private CompositeByteBuf body;
    private ScheduledFuture<?> deadline;
    private boolean readWhenWritable;

    Connection(Router router, RequestGate gate, int maxBody, long timeoutMillis) {
        this.router = router;
        this.gate = gate;
        this.maxBody = maxBody;
        this.timeoutMillis = timeoutMillis;
    }

    /** Goes first in the pipeline, ahead of the decoder: the request timer starts with the first bytes. */
    ChannelInboundHandlerAdapter bytesWatch() {
        return new ChannelInboundHandlerAdapter() {
            @Override
            public void channelRead(ChannelHandlerContext c, Object msg) {
                if (state == State.IDLE && msg instanceof ByteBuf b && b.isReadable()) {
                    startReading();
                }
                c.fireChannelRead(msg);
            }
        };
    }

    @Override
    public void handlerAdded(ChannelHandlerContext context) {
        ctx = context;
    }

    @Override
    public void channelActive(ChannelHandlerContext context) {
        context.read();
        context.fireChannelActive();
    }

    @Override
    public void channelRead(ChannelHandlerContext context, Object msg) {
        try {
            if (state == State.BUSY || state == State.CLOSING) {
                return; // cannot happen while reads wait for answers; never act on it
            }
            if (msg instanceof HttpRequest request) {
                begin(request);
            }
            if (msg instanceof HttpContent content && head != null) {
                content(content);
            }
        } finally {
            ReferenceCountUtil.release(msg);
        }
    }

    private void begin(HttpRequest request) {
        if (state == State.IDLE) {
            startReading(); // taken from the flow control's queue: no new bytes were needed
        }
        head = request;
        DecoderResult decoded = request.decoderResult();
        if (!decoded.isSuccess()) {
            Throwable cause = decoded.cause();
            if (cause instanceof TooLongHttpLineException) {
                refuse(414, "the request line is too long (at most " + HttpServer.MAX_LINE
                        + " bytes for method, path and query)");
            } else if (cause instanceof TooLongHttpHeaderException) {
                refuse(431, "the request headers are too large (at most " + HttpServer.MAX_HEADERS + " bytes)");
            } else {
                refuse(400, "malformed HTTP request: " + cause.getMessage());
            }
            return;
        }
        long declared = HttpUtil.getContentLength(request, -1L);
        if (declared > maxBody) {
            refuse(413, "the body is too large: Content-Length " + declared + " > " + maxBody + " bytes");
            return;
        }
        String expect = request.headers().get(HttpHeaderNames.EXPECT);
        if (expect != null) {
            if (!expect.equalsIgnoreCase(HttpHeaderValues.CONTINUE.toString())) {
                refuse(417, "unsupported Expect: " + expect + " (only 100-continue)");
                return;
            }
            ctx.writeAndFlush(new DefaultFullHttpResponse(request.protocolVersion(), HttpResponseStatus.CONTINUE,
                    Unpooled.EMPTY_BUFFER), ctx.voidPromise());
        }
        body = ctx.alloc().compositeBuffer();
        ctx.read(); // the body, or at least its end
    }

    private void content(HttpContent content) {
        if (!content.decoderResult().isSuccess()) {
            refuse(400, "malformed HTTP body: " + content.decoderResult().cause().getMessage());
            return;
        }
        if (body.readableBytes() + content.content().readableBytes() > maxBody) {
            refuse(413, "the body is too large: more than " + maxBody + " bytes");
            return;
        }
        body.addComponent(true, content.content().retain());
        if (content instanceof LastHttpContent) {
            dispatch();
        } else {
            ctx.read();
        }
    }

    private void dispatch() {
        cancelDeadline();
        state = State.BUSY;
        HttpRequest request = head;
        byte[] bytes = new byte[body.readableBytes()];
        body.readBytes(bytes);
        discardRequest();
        String uri = request.uri();
        int query = uri.indexOf('?');
        ServerExchange ex = new ServerExchange(ctx, this, request.method(), query < 0 ? uri : uri.substring(0, query), bytes,
                HttpUtil.isKeepAlive(request), request.protocolVersion(), request.headers().get(CommanderHeader.NAME));
        try {
            gate.check(request.method(), request.protocolVersion(), request.headers(), localPort());
            router.route(ex);
        } catch (ApiException e) {
            ex.error(e);
        } catch (RuntimeException e) {
            Replies.fail(ex, e);
        }
    }

    /** Answers a request that could not be read whole, and closes the connection after the answer. */
    private void refuse(int status, String message) {
        cancelDeadline();
        state = State.BUSY;
        HttpMethod method = head != null && head.decoderResult().isSuccess() ? head.method() : HttpMethod.GET;
        String path = head != null && head.decoderResult().isSuccess() ? head.uri() : "/";
        HttpVersion version = head != null ? head.protocolVersion() : HttpVersion.HTTP_1_1;
        discardRequest();
        new ServerExchange(ctx, this, method, path, new byte[0], false, version).error(status, null, message, null);
    }

    /** Writes the answer of the request in progress; on the event loop. */
    void answer(FullHttpResponse response, boolean keepAlive) {
        if (state != State.BUSY) {
            ReferenceCountUtil.release(response); // the connection went away meanwhile
            return;
        }
        if (!keepAlive) {
            state = State.CLOSING;
            ctx.writeAndFlush(response).addListener(ChannelFutureListener.CLOSE);
            return;
        }
        state = State.IDLE;
        ctx.writeAndFlush(response, ctx.voidPromise());
        if (ctx.channel().isWritable()) {
            ctx.read();
        } else {
            readWhenWritable = true; // the client does not read its answers: read no more requests meanwhile
        }
    }

    /** Closes without an answer (fault: dropped connection); on the event loop. */
    void drop() {
        state = State.CLOSING;
        ctx.close();
    }

    @Override
    public void channelWritabilityChanged(ChannelHandlerContext context) {
        if (readWhenWritable && context.channel().isWritable()) {
            readWhenWritable = false;
            context.read();
        }
        context.fireChannelWritabilityChanged();
    }

    private void startReading() {
        state = State.READING;
        deadline = ctx.executor().schedule(this::timedOut, timeoutMillis, TimeUnit.MILLISECONDS);
    }

    private void timedOut() {
        deadline = null;
        if (state == State.READING) {
            refuse(408, "the request did not arrive whole within " + timeoutMillis + " ms (send headers and body "
                    + "at once)");
        }
    }

    private void cancelDeadline() {
        if (deadline != null) {
            deadline.cancel(false);
            deadline = null;
        }
    }

    private void discardRequest() {
        head = null;
        if (body != null) {
            body.release();
            body = null;
        }
    }

    private int localPort() {
        return ((InetSocketAddress) ctx.channel().localAddress()).getPort();
    }

    @Override
    public void channelInactive(ChannelHandlerContext context) {
        state = State.CLOSING;
        cancelDeadline();
        discardRequest();
        context.fireChannelInactive();
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext context, Throwable cause) {
        if (!(cause instanceof IOException)) {
            System.err.println("robot-sim: connection error: " + cause);
        }
        context.close();
    }
}
