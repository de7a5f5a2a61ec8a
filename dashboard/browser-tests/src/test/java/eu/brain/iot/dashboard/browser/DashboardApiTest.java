package eu.brain.iot.dashboard.browser;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;

import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * The dashboard's HTTP API on the real node, without a browser: JSON errors on every path and method, and a stream
 * that resumes after {@code Last-Event-ID} with the events missed, or starts with a snapshot when it cannot.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class DashboardApiTest {

    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    static Path home;

    @AutoClose
    private RobotSim sim;
    @AutoClose
    private Node node;

    @BeforeAll
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        node = new Node(home.resolve("node"), sim.baseUri(), 100, false).start();
    }

    @Test
    void answersEveryWrongPathAndMethodWithAJsonError() throws Exception {
        expectError("GET", "dashboard/api/nope", 404, "/dashboard/api/snapshot");
        expectError("GET", "dashboard/nope.js", 404, "/dashboard/");
        // a path climbing out with an encoded "..": Jetty refuses it before any servlet sees it, never served; with a
        // JSON error too (the edge's JettySetup installs its JSON error handler on the whole server). A plain ".."
        // is resolved by Jetty within the server (/dashboard/../x is /x), behind the gate of where it lands.
        for (String climbing : new String[] { "dashboard/%2e%2e/web/index.html", "dashboard/%2E%2E/%2e%2e/etc/passwd",
                "dashboard/api/%2e%2e/%2e%2e/sensinact" }) {
            HttpResponse<String> r = send("GET", climbing);
            assertThat(r.statusCode()).as(climbing + ": " + r.body()).isEqualTo(400);
            assertThat(r.headers().firstValue("Content-Type").orElse("")).as(climbing).startsWith("application/json");
            assertThat(JSON.readTree(r.body()).get("status").asInt()).isEqualTo(400);
        }
        HttpResponse<String> post = expectError("POST", "dashboard/api/snapshot", 405, "read-only");
        assertThat(post.headers().firstValue("Allow")).contains("GET, HEAD");
        expectError("DELETE", "dashboard/api/stream", 405, "read-only");
        expectError("PUT", "dashboard/index.html", 405, "read-only");

        HttpResponse<String> page = send("GET", "dashboard/");
        assertThat(page.statusCode()).isEqualTo(200);
        assertThat(page.headers().firstValue("Content-Type").orElse("")).startsWith("text/html");
        assertThat(send("GET", "dashboard").statusCode()).isEqualTo(302);
    }

    @Test
    void resumesAfterTheLastEventIdOrStartsWithASnapshot() throws Exception {
        String snapshotId;
        String deltaId;
        try (Stream s = new Stream(null)) {
            Map<String, String> first = s.next();
            assertThat(first).containsEntry("event", "snapshot");
            snapshotId = first.get("id");
            node.post("sensinact/providers/door1/services/control/resources/open/act", "{}");
            Map<String, String> delta = s.next();
            assertThat(delta).containsEntry("event", "delta");
            deltaId = delta.get("id");
        }
        try (Stream s = new Stream(snapshotId)) {
            Map<String, String> replayed = s.next();
            assertThat(replayed).as("the missed event, not a snapshot").containsEntry("event", "delta")
                    .containsEntry("id", deltaId);
        }
        try (Stream s = new Stream("x0x0-5")) {
            assertThat(s.next()).as("an id of another node's start").containsEntry("event", "snapshot");
        }
    }

    private HttpResponse<String> expectError(String method, String path, int status, String saying) throws Exception {
        HttpResponse<String> r = send(method, path);
        JsonErrors.assertJsonError(r, status, saying);
        return r;
    }

    private HttpResponse<String> send(String method, String path) throws Exception {
        // the path as given (no normalisation of "..": the server must refuse it itself)
        URI uri = URI.create(node.base() + path);
        return HTTP.send(HttpRequest.newBuilder(uri).timeout(Duration.ofSeconds(10))
                .method(method, HttpRequest.BodyPublishers.noBody()).build(), HttpResponse.BodyHandlers.ofString());
    }

    /** An SSE stream of the dashboard, read event by event. */
    private final class Stream implements AutoCloseable {
        private final InputStream body;
        private final BufferedReader lines;

        Stream(String lastEventId) throws Exception {
            HttpRequest.Builder b = HttpRequest.newBuilder(node.base().resolve("dashboard/api/stream"));
            if (lastEventId != null) {
                b.header("Last-Event-ID", lastEventId);
            }
            HttpResponse<InputStream> r = HTTP.send(b.build(), HttpResponse.BodyHandlers.ofInputStream());
            assertThat(r.statusCode()).isEqualTo(200);
            assertThat(r.headers().firstValue("Content-Type").orElse("")).startsWith("text/event-stream");
            body = r.body();
            lines = new BufferedReader(new InputStreamReader(body, StandardCharsets.UTF_8));
        }

        /** The next event's fields (comments skipped); fails after 30 s without one. */
        Map<String, String> next() throws Exception {
            return java.util.concurrent.CompletableFuture.supplyAsync(() -> {
                try {
                    return read();
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }).get(30, java.util.concurrent.TimeUnit.SECONDS);
        }

        private Map<String, String> read() throws java.io.IOException {
            Map<String, String> fields = new LinkedHashMap<>();
            for (String line; (line = lines.readLine()) != null;) {
                if (line.isEmpty()) {
                    if (!fields.isEmpty()) {
                        return fields;
                    }
                } else if (!line.startsWith(":")) {
                    int colon = line.indexOf(':');
                    fields.put(line.substring(0, colon), line.substring(colon + 1).strip());
                }
            }
            throw new AssertionError("the stream ended");
        }

        @Override
        public void close() throws Exception {
            body.close();
        }
    }
}
