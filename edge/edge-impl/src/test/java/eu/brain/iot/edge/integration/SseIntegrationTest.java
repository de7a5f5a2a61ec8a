package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static eu.brain.iot.edge.integration.EdgeTestSupport.JSON;
import static eu.brain.iot.edge.integration.RestReadIntegrationTest.assertError;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.osgi.service.log.LogEntry;
import org.osgi.service.log.LogLevel;
import org.osgi.service.log.LogReaderService;
import org.osgi.service.log.Logger;
import org.osgi.service.log.admin.LoggerAdmin;
import org.osgi.test.common.annotation.InjectService;

import com.fasterxml.jackson.databind.JsonNode;


/** The SSE stream of changes: what it sends, its heartbeat, and the end of a client's subscription. */
class SseIntegrationTest extends EdgeRestTestBase {

    @InjectService(timeout = 10_000)
    static LogReaderService logs;
    @InjectService(timeout = 10_000)
    static LoggerAdmin loggers;
    static final String REST_BUNDLE = "eu.brain.iot.edge.rest";

    @BeforeAll
    static void configure() throws Exception {
        // frequent heartbeats, so that a client that left is noticed within the test's patience
        edge.configureRest(Map.of("sse.heartbeat.ms", 200L));
        // the edge's REST bundle says at INFO when a client left (a logger context is named after its bundle)
        loggers.getLoggerContext(REST_BUNDLE).setLogLevels(Map.of(Logger.ROOT_LOGGER_NAME, LogLevel.INFO));
    }

    @AfterAll
    static void resetLogLevels() {
        loggers.getLoggerContext(REST_BUNDLE).setLogLevels(Map.of());
    }

    /** An open stream: its lines, read on a thread of its own. */
    private static final class Stream implements AutoCloseable {
        final HttpResponse<InputStream> response;
        final List<String> lines = new CopyOnWriteArrayList<>();
        private final Thread reader;

        Stream(String query) throws Exception {
            HttpRequest request = HttpRequest.newBuilder(edge.uri("/sensinact/subscribe" + query)).GET().build();
            response = edge.http().send(request, HttpResponse.BodyHandlers.ofInputStream());
            reader = new Thread(() -> {
                try (BufferedReader in = new BufferedReader(new InputStreamReader(response.body(),
                        StandardCharsets.UTF_8))) {
                    for (String line; (line = in.readLine()) != null;) {
                        lines.add(line);
                    }
                } catch (IOException e) {
                    // closed by the test
                }
            }, "sse-test-reader");
            reader.setDaemon(true);
            reader.start();
        }

        List<JsonNode> events() throws IOException {
            List<JsonNode> events = new java.util.ArrayList<>();
            for (String line : lines) {
                if (line.startsWith("data: ")) {
                    events.add(JSON.readTree(line.substring(6)));
                }
            }
            return Collections.unmodifiableList(events);
        }

        @Override
        public void close() throws IOException {
            response.body().close();
        }
    }

    @Test
    void streamsTheChangesOfOneProvidersService() throws Exception {
        try (Stream stream = new Stream("?provider=robot2&service=position")) {
            assertThat(stream.response.statusCode()).isEqualTo(200);
            assertThat(stream.response.headers().firstValue("Content-Type")).hasValueSatisfying(
                    t -> assertThat(t).startsWith("text/event-stream"));
            await().atMost(DEADLINE).until(() -> stream.lines.stream().anyMatch(l -> l.startsWith(": subscribed")));

            int x = edge.sim.robot("robot2").x();
            assertThat(model.act("robot2", "control", "goTo", Map.of("x", x, "y", 3)).toCompletableFuture().join()
                    .accepted).isTrue();
            model.act("door1", "control", "open", Map.of()).toCompletableFuture().join(); // not robot2: not sent
            edge.sim.step(4);

            await().atMost(DEADLINE).untilAsserted(() -> assertThat(stream.events()).anySatisfy(e -> {
                assertThat(e.get("resource").asText()).isEqualTo("y");
                assertThat(e.get("value").asInt()).isEqualTo(3);
                assertThat(e.get("status").asText()).isEqualTo("OK");
                assertThat(e.get("timestamp").asText()).endsWith("Z");
            }));
            assertThat(stream.events()).allSatisfy(e -> {
                assertThat(e.get("provider").asText()).isEqualTo("robot2");
                assertThat(e.get("service").asText()).isEqualTo("position");
            });
            // heartbeat comments keep the stream alive and find clients that left
            await().atMost(DEADLINE).until(() -> stream.lines.contains(": heartbeat"));
        }
    }

    @Test
    void aClientThatLeavesLosesItsSubscription() throws Exception {
        Stream stream = new Stream("?provider=robot1");
        await().atMost(DEADLINE).until(() -> stream.lines.stream().anyMatch(l -> l.startsWith(": subscribed")));
        String local = "(provider=robot1, service=*)";
        stream.close();
        await("the edge notices the client left").atMost(DEADLINE).until(() -> {
            for (LogEntry entry : Collections.list(logs.getLog())) {
                if (entry.getMessage().contains("SSE client") && entry.getMessage().contains(local)
                        && entry.getMessage().contains("disconnected")) {
                    return true;
                }
            }
            return false;
        });
    }

    @Test
    void badSubscriptionsAnswerJsonErrors() throws Exception {
        assertError(edge.get("/sensinact/subscribe?provider=robot9"), 404, "no provider 'robot9'", "robot1");
        assertError(edge.get("/sensinact/subscribe?robot=robot1"), 400, "unknown query parameter 'robot'",
                "provider", "service");
        HttpResponse<String> r = edge.post("/sensinact/subscribe", "{}");
        assertError(r, 405, "POST is not allowed", "GET");
    }
}
