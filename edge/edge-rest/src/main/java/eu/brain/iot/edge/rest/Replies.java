package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.ObjectMapper;

import jakarta.servlet.http.HttpServletResponse;

/**
 * Writes JSON answers, errors included: every error is {@code {"error": "...", "field": "...", "status": N}}
 * ({@code field} only when one header, parameter or the body is at fault), never a stack trace. Jetty's own errors
 * have the same shape ({@link JsonErrorHandler}).
 */
final class Replies {

    /** Thread-safe once configured; shared by every request. */
    static final ObjectMapper MAPPER = new ObjectMapper().disable(JsonGenerator.Feature.AUTO_CLOSE_TARGET);

    private Replies() {
    }

    static void json(HttpServletResponse resp, int status, Object body) throws IOException {
        resp.setStatus(status);
        resp.setContentType("application/json");
        resp.setCharacterEncoding("UTF-8");
        // live values: a cached answer would be a stale one
        resp.setHeader("Cache-Control", "no-store");
        // a known length: the answer is complete without waiting for the connection's end (a 413 closes it only
        // once Jetty has given up on the body it was announced)
        byte[] bytes = MAPPER.writeValueAsBytes(body);
        resp.setContentLength(bytes.length);
        resp.getOutputStream().write(bytes);
    }

    static void error(HttpServletResponse resp, HttpError e) throws IOException {
        if (e.allow != null) {
            resp.setHeader("Allow", e.allow);
        }
        if (e.close) {
            resp.setHeader("Connection", "close");
        }
        if (e.status == 401) {
            resp.setHeader("WWW-Authenticate", "Bearer realm=\"brain-iot edge\"");
        }
        json(resp, e.status, error(e.status, e.field, e.getMessage()));
    }

    static Map<String, Object> error(int status, String message) {
        return error(status, null, message);
    }

    static Map<String, Object> error(int status, String field, String message) {
        Map<String, Object> body = new LinkedHashMap<>();
        body.put("error", message);
        if (field != null) {
            body.put("field", field);
        }
        body.put("status", status);
        return body;
    }
}
