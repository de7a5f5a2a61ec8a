package eu.brain.iot.edge.impl;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.http.FullHttpResponse;

/** Hands each answer, or the connection's end, to the connection's current {@link InFlightRequest}. */
final class AnswerHandler extends SimpleChannelInboundHandler<FullHttpResponse> {

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, FullHttpResponse response) {
        InFlightRequest request = ctx.channel().attr(InFlightRequest.KEY).get();
        if (request == null) {
            ctx.close(); // an answer nobody asked for: this connection cannot be trusted any more
            return;
        }
        request.complete(response);
    }

    @Override
    public void channelInactive(ChannelHandlerContext ctx) throws Exception {
        InFlightRequest request = ctx.channel().attr(InFlightRequest.KEY).get();
        if (request != null) {
            request.fail("the device closed the connection without answering");
        }
        super.channelInactive(ctx);
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        InFlightRequest request = ctx.channel().attr(InFlightRequest.KEY).get();
        if (request != null) {
            request.fail("connection error: " + cause.getMessage());
        } else {
            ctx.close();
        }
    }
}
