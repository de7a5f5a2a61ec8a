package eu.brain.iot.dashboard;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.LinkedHashMap;
import java.util.Map;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;

import jakarta.servlet.http.HttpServletResponse;

/** JSON for the page: answers and errors; every error is {@code {"error": "...", "status": N}} ({@code "field"} too when one header is at fault), never a stack trace. */
final class Json {

    /** Thread-safe once configured; shared by every thread. */
    private static final ObjectMapper MAPPER = new ObjectMapper().disable(JsonGenerator.Feature.AUTO_CLOSE_TARGET);

    private Json() {
    }

    static String write(Object value) {
        try {
            return MAPPER.writeValueAsString(value);
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** JSON text written as it is inside a larger answer. */
    static Object raw(String json) {
        return new com.fasterxml.jackson.databind.util.RawValue(json);
    }

    /** Longer than any path of the dashboard: what an error may repeat of a request. */
    static final int MAX_ECHO_CHARS = 120;

    /** Request text (a path) as an error message may repeat it: cut, with its length, when long. */
    static String echo(String text) {
        if (text == null || text.length() <= MAX_ECHO_CHARS) {
            return text;
        }
        return text.substring(0, MAX_ECHO_CHARS) + "... (" + text.length() + " characters)";
    }

    static void answer(HttpServletResponse resp, int status, String json) throws IOException {
        resp.setStatus(status);
        resp.setContentType("application/json");
        resp.setCharacterEncoding("UTF-8");
        resp.setHeader("Cache-Control", "no-store"); // live values: a cached answer would be a stale one
        resp.getWriter().write(json);
    }

    static void error(HttpServletResponse resp, int status, String message) throws IOException {
        error(resp, status, message, null);
    }

    /** An error about one header ({@code field}: {@code Host}, {@code Authorization}...), or {@code null}. */
    static void error(HttpServletResponse resp, int status, String message, String field) throws IOException {
        Map<String, Object> body = new LinkedHashMap<>();
        body.put("error", message);
        if (field != null) {
            body.put("field", field);
        }
        body.put("status", status);
        answer(resp, status, write(body));
    }
}
