package eu.brain.iot.robotsim.http;

import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelHandler;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.http.FullHttpRequest;
import io.netty.handler.codec.http.HttpUtil;
import io.netty.handler.codec.http.HttpVersion;
import java.io.IOException;

/** Turns each decoded HTTP request into an {@link Exchange} for the {@link Router}. Stateless, so shared. */
@ChannelHandler.Sharable
final class RequestHandler extends SimpleChannelInboundHandler<FullHttpRequest> {
    private static final byte[] EMPTY = new byte[0];
    private final Router router;

    RequestHandler(Router router) {
        this.router = router;
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, FullHttpRequest request) {
        boolean keepAlive = HttpUtil.isKeepAlive(request);
        HttpVersion version = request.protocolVersion();
        String uri = request.uri();
        int query = uri.indexOf('?');
        String path = query < 0 ? uri : uri.substring(0, query);
        byte[] body = request.content().isReadable() ? ByteBufUtil.getBytes(request.content()) : EMPTY;
        Exchange ex = new Exchange(ctx, request.method(), path, body, keepAlive, version);
        if (!request.decoderResult().isSuccess()) {
            ex.error(400, null, "malformed HTTP request: " + request.decoderResult().cause(), null);
            return;
        }
        try {
            router.route(ex);
        } catch (RuntimeException e) {
            Replies.fail(ex, e);
        }
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        if (!(cause instanceof IOException)) {
            System.err.println("robot-sim: connection error: " + cause);
        }
        ctx.close();
    }
}
