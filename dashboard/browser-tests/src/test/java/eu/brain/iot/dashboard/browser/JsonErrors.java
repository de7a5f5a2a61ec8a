package eu.brain.iot.dashboard.browser;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.http.HttpResponse;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** The node's JSON error answers, as the tests check them: {@code {"error": "...", "field": "...", "status": N}}. */
final class JsonErrors {

    private static final ObjectMapper JSON = new ObjectMapper();

    private JsonErrors() {
    }

    /** Asserts a JSON error with this status whose message contains {@code saying} (unless null); returns it. */
    static JsonNode assertJsonError(HttpResponse<String> r, int status, String saying) throws JsonProcessingException {
        assertThat(r.statusCode()).as(r.request().method() + " " + r.uri() + ": " + r.body()).isEqualTo(status);
        assertThat(r.headers().firstValue("Content-Type").orElse("")).startsWith("application/json");
        JsonNode body = JSON.readTree(r.body());
        assertThat(body.get("status").asInt()).isEqualTo(status);
        if (saying != null) {
            assertThat(body.get("error").asText()).contains(saying);
        }
        return body;
    }
}
