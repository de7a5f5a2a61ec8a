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
    void servesAFaviconAndDoesNotEchoALongPathWhole() throws Exception {
        HttpResponse<String> icon = send("GET", "favicon.ico");
        assertThat(icon.statusCode()).isEqualTo(200);
        assertThat(icon.headers().firstValue("Content-Type").orElse("")).startsWith("image/svg+xml");
        assertThat(icon.body()).startsWith("<svg");
        assertThat(send("GET", "dashboard/").body()).contains("rel=\"icon\"");

        String longName = "a".repeat(6_000);
        for (String path : new String[] { "dashboard/" + longName + ".js", "dashboard/api/" + longName }) {
            HttpResponse<String> r = expectError("GET", path, 404, "characters)");
            assertThat(r.body().length()).isLessThan(1_000);
        }
    }

    @Test
    void aRequestWithTwoOriginHeadersIsRefused() throws Exception {
        String origin = "http://" + node.base().getHost() + ":" + node.base().getPort();
        try (java.net.Socket s = new java.net.Socket(node.base().getHost(), node.base().getPort())) {
            s.setSoTimeout(10_000);
            s.getOutputStream().write(("GET /dashboard/api/snapshot HTTP/1.1\r\nHost: " + node.base().getHost() + ":"
                    + node.base().getPort() + "\r\nOrigin: " + origin + "\r\nOrigin: http://evil.example\r\n"
                    + "Connection: close\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
            String answer = new String(s.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(answer).startsWith("HTTP/1.1 400 ").contains("2 Origin headers");
        }
    }

    @Test
    void streamsAreCappedSoThatOtherRequestsKeepTheirConnections() throws Exception {
        int cap = 64; // max.streams' default
        java.util.List<java.net.Socket> streams = new java.util.ArrayList<>();
        try {
            int refused = 0;
            for (int i = 0; i < cap + 10; i++) {
                java.net.Socket s = new java.net.Socket(node.base().getHost(), node.base().getPort());
                s.setSoTimeout(10_000);
                streams.add(s);
                s.getOutputStream().write(("GET /dashboard/api/stream HTTP/1.1\r\nHost: " + node.base().getHost()
                        + ":" + node.base().getPort() + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
                StringBuilder status = new StringBuilder();
                for (int b; (b = s.getInputStream().read()) >= 0 && b != '\n';) {
                    status.append((char) b);
                }
                if (status.toString().contains(" 503 ")) {
                    refused++;
                    s.close();
                }
            }
            // other streams of this test class may be open: at least the 10 over the cap are refused
            assertThat(refused).isGreaterThanOrEqualTo(10);
            HttpResponse<String> snapshot = send("GET", "dashboard/api/snapshot");
            assertThat(snapshot.statusCode()).isEqualTo(200);
            expectError("GET", "dashboard/api/stream", 503, "max.streams");
        } finally {
            for (java.net.Socket s : streams) {
                s.close();
            }
        }
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
