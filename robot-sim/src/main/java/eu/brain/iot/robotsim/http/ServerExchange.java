package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.view.Json;
import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.http.DefaultFullHttpResponse;
import io.netty.handler.codec.http.FullHttpResponse;
import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpHeaderValues;
import io.netty.handler.codec.http.HttpMethod;
import io.netty.handler.codec.http.HttpResponseStatus;
import io.netty.handler.codec.http.HttpVersion;
import io.netty.util.AsciiString;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * One request robot-sim received and the answer it gives (the server side of an HTTP exchange). Created on a Netty I/O thread; may be answered from any thread: the answer is handed to
 * the connection's event loop, where the {@link Connection} writes it and reads the next request. Fault injection
 * hooks in here: added latency and malformed bodies. A HEAD request gets the headers of the GET answer, no body.
 */
final class ServerExchange {
    private static final AsciiString APPLICATION_JSON = AsciiString.cached("application/json");

    private final ChannelHandlerContext ctx;
    private final Connection connection;
    private final HttpMethod method;
    private final String path;
    private final byte[] body;
    private final boolean keepAlive;
    private final HttpVersion version;
    private final String commander;
    private int delayMs;
    private boolean malformed;
    private CommandCounter commands;

    ServerExchange(ChannelHandlerContext ctx, Connection connection, HttpMethod method, String path, byte[] body,
             boolean keepAlive, HttpVersion version) {
        this(ctx, connection, method, path, body, keepAlive, version, null);
    }

    /** @param commander the request's {@value CommanderHeader#NAME} header, null when it had none */
    ServerExchange(ChannelHandlerContext ctx, Connection connection, HttpMethod method, String path, byte[] body,
             boolean keepAlive, HttpVersion version, String commander) {
        this.commander = commander;
        this.ctx = ctx;
        this.connection = connection;
        this.method = method;
        this.path = path;
        this.body = body;
        this.keepAlive = keepAlive;
        this.version = version;
    }

    HttpMethod method() {
        return method;
    }

    String path() {
        return path;
    }

    byte[] body() {
        return body;
    }

    /** The request's {@value CommanderHeader#NAME} header as sent, null when it had none. */
    String commander() {
        return commander;
    }

    /** This exchange is a command: its answer (or its drop) is counted. */
    void countAsCommand(CommandCounter counter) {
        commands = counter;
    }

    /** Delays the answer (fault: latency). */
    void delay(int millis) {
        delayMs = millis;
    }

    /** Truncates the JSON of the answer (fault: malformed JSON). */
    void malformed() {
        malformed = true;
    }

    void json(int status, Object value) {
        send(status, Json.bytes(value), null);
    }

    void json(int status, byte[] json) {
        send(status, json, null);
    }

    void error(ApiException e) {
        error(e.status(), e.field(), e.getMessage(), null);
    }

    void error(int status, String field, String message, String allow) {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("error", message);
        doc.put("field", field);
        doc.put("status", status);
        send(status, Json.bytes(doc), allow);
    }

    /** Closes the connection without an answer (fault: dropped connection). */
    void drop() {
        if (commands != null) {
            commands.record(0);
        }
        onEventLoop(delayMs, connection::drop);
    }

    private void send(int status, byte[] json, String allow) {
        if (commands != null) {
            commands.record(status);
        }
        byte[] content = malformed ? truncate(json) : json;
        boolean head = method.equals(HttpMethod.HEAD);
        FullHttpResponse response = new DefaultFullHttpResponse(version, HttpResponseStatus.valueOf(status),
                head ? Unpooled.EMPTY_BUFFER : Unpooled.wrappedBuffer(content));
        response.headers()
                .set(HttpHeaderNames.CONTENT_TYPE, APPLICATION_JSON)
                .setInt(HttpHeaderNames.CONTENT_LENGTH, content.length);
        if (allow != null) {
            response.headers().set(HttpHeaderNames.ALLOW, allow);
        }
        if (keepAlive && version.equals(HttpVersion.HTTP_1_0)) {
            response.headers().set(HttpHeaderNames.CONNECTION, HttpHeaderValues.KEEP_ALIVE);
        } else if (!keepAlive) {
            response.headers().set(HttpHeaderNames.CONNECTION, HttpHeaderValues.CLOSE);
        }
        onEventLoop(delayMs, () -> connection.answer(response, keepAlive));
    }

    private void onEventLoop(int delay, Runnable task) {
        if (delay > 0) {
            ctx.executor().schedule(task, delay, TimeUnit.MILLISECONDS);
        } else if (ctx.executor().inEventLoop()) {
            task.run();
        } else {
            ctx.executor().execute(task);
        }
    }

    /** Cuts a JSON document in the middle (and never to a complete document). */
    static byte[] truncate(byte[] json) {
        int keep = Math.max(1, json.length / 2);
        byte[] cut = new byte[keep];
        System.arraycopy(json, 0, cut, 0, keep);
        if (cut[keep - 1] == '}' || cut[keep - 1] == ']') {
            cut[keep - 1] = ',';
        }
        return cut;
    }

    static String utf8(byte[] bytes) {
        return new String(bytes, StandardCharsets.UTF_8);
    }
}
