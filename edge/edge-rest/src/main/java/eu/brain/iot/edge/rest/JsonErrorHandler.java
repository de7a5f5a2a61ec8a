package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;

import org.eclipse.jetty.http.HttpFields;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.handler.ErrorHandler;

import com.fasterxml.jackson.core.JsonProcessingException;

import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * Jetty's error pages as the API's JSON errors ({@code {"error", "status"}}), never HTML: the errors Jetty's parser
 * answers before any servlet runs (400 malformed request or URI, 414 URI too long, 431 headers too large:
 * {@link #badMessageError}) and those of requests no servlet takes (404 outside {@code /sensinact}, 405, 500:
 * {@link #generateAcceptableResponse}). Installed on Felix HTTP's Jetty server by {@link JettySetup}.
 * <p>
 * Threads: Jetty's, any number at once; stateless.
 */
final class JsonErrorHandler extends ErrorHandler {

    JsonErrorHandler() {
        setShowStacks(false);
        setShowServlet(false);
    }

    @Override
    public boolean errorPageForMethod(String method) {
        return true; // every method gets its JSON error (Jetty's default: GET, POST and HEAD only)
    }

    @Override
    public ByteBuffer badMessageError(int status, String reason, HttpFields.Mutable fields) {
        fields.put(HttpHeader.CONTENT_TYPE, "application/json");
        fields.put(HttpHeader.CACHE_CONTROL, "no-store");
        return ByteBuffer.wrap(body(status, parserMessage(status, reason)));
    }

    @Override
    protected void generateAcceptableResponse(Request baseRequest, HttpServletRequest request,
            HttpServletResponse response, int code, String message) throws IOException {
        baseRequest.setHandled(true);
        response.setContentType("application/json");
        response.setCharacterEncoding("UTF-8");
        response.setHeader("Cache-Control", "no-store");
        byte[] body = body(code, servletMessage(code, message, request));
        response.setContentLength(body.length);
        try {
            response.getOutputStream().write(body);
        } catch (IllegalStateException e) {
            response.getWriter().write(new String(body, StandardCharsets.UTF_8)); // the failed request took a writer
        }
    }

    static String parserMessage(int status, String reason) {
        String what = reason == null ? "" : " (" + reason + ")";
        return switch (status) {
            case 414 -> "the request's URI is too long" + what + "; paths and queries of this API are short";
            case 431 -> "the request's headers are too large" + what + "; send fewer or shorter headers";
            case 400 -> "malformed HTTP request" + what + "; check the request line, the headers and the "
                    + "percent-encoding of the path (UTF-8)";
            default -> "the HTTP request was refused" + what;
        };
    }

    private static String servletMessage(int code, String message, HttpServletRequest request) {
        String uri = Echo.cut(request.getRequestURI());
        if (code == 404) {
            return "no such path: " + uri + "; the edge's REST API is under " + Route.ROOT + " (GET " + Route.ROOT
                    + " lists its paths)";
        }
        String text = message == null || message.isBlank() ? "HTTP error " + code : message;
        return code >= 500 ? "internal error on " + uri + " (" + text + "); the node's log has the details"
                : text + " (" + request.getMethod() + " " + uri + ")";
    }

    static byte[] body(int status, String message) {
        try {
            return Replies.MAPPER.writeValueAsBytes(Replies.error(status, message));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a map of strings is always JSON", e);
        }
    }
}
