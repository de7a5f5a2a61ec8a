package eu.brain.iot.edge.rest.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.Socket;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.osgi.service.log.LogEntry;
import org.osgi.service.log.LogLevel;
import org.osgi.service.log.LogReaderService;
import org.osgi.test.common.annotation.InjectService;

/**
 * The HTTP surface as a client on loopback meets it: event streams cannot take every connection, a request with two
 * {@code Origin} headers is refused, an unknown path is not echoed whole, and an invalid {@code auth} value leaves the
 * API up with the safe default.
 */
class SurfaceIntegrationTest extends RestTestBase {

    static final Duration PATIENCE = Duration.ofSeconds(5);

    @InjectService(timeout = 10_000)
    static LogReaderService logs;

    @AfterEach
    void defaults() throws Exception {
        configure(Map.of("max.connections", 1_000, "sse.max.streams", 256, "auth", "auto"));
    }

    private static String subscribe() {
        return "GET /sensinact/subscribe HTTP/1.1\r\n" + RawHttp.host(base) + "\r\n\r\n";
    }

    /** The status line of the answer to a request sent on an open socket, read without waiting for a stream's end. */
    private static String statusLine(Socket s) throws IOException {
        StringBuilder line = new StringBuilder();
        for (int b; (b = s.getInputStream().read()) >= 0 && b != '\n';) {
            line.append((char) b);
        }
        return line.toString().strip();
    }

    @Test
    void eventStreamsFromOneMachineCannotTakeEveryConnection() throws Exception {
        configure(Map.of("max.connections", 100, "sse.max.streams", 40));
        List<Socket> streams = new ArrayList<>();
        List<String> statuses = new ArrayList<>();
        try {
            for (int i = 0; i < 100; i++) { // as many as the server accepts in total, all from 127.0.0.1
                Socket s = RawHttp.connect(base, null);
                streams.add(s);
                s.getOutputStream().write(subscribe().getBytes(StandardCharsets.US_ASCII));
                s.getOutputStream().flush();
                String status = statusLine(s);
                statuses.add(status);
                if (!status.endsWith(" 200 OK")) {
                    s.close(); // as a client does once it has its answer (the server closes its side after a 503)
                }
            }
            assertThat(statuses.stream().filter(l -> l.endsWith(" 200 OK")).count()).isEqualTo(40);
            assertThat(statuses.stream().filter(l -> l.contains(" 503 ")).count()).isEqualTo(60);
            RawHttp.Answer refused = raw("GET /sensinact/subscribe HTTP/1.1\r\n" + RawHttp.host(base), null);
            assertError(refused, 503, "too many event streams", "sse.max.streams");

            // others are served: the refused streams' connections were closed, the 40 streams leave room
            HttpResponse<String> r = HTTP.send(HttpRequest.newBuilder(uri("/sensinact/providers")).timeout(PATIENCE)
                    .build(), HttpResponse.BodyHandlers.ofString());
            assertThat(r.statusCode()).isEqualTo(200);
            assertThat(entries("streams open, the most allowed")).singleElement()
                    .satisfies(e -> assertThat(e.getLogLevel()).isEqualTo(LogLevel.WARN));

            streams.get(0).close(); // a stream ends: a new one is accepted
            await("a stream once one closed").atMost(DEADLINE).until(() -> {
                try (Socket s = RawHttp.connect(base, null)) {
                    s.getOutputStream().write(subscribe().getBytes(StandardCharsets.US_ASCII));
                    return statusLine(s).endsWith(" 200 OK");
                }
            });
        } finally {
            for (Socket s : streams) {
                s.close();
            }
        }
    }

    @Test
    void aRequestWithTwoOriginHeadersIsRefused() throws Exception {
        String origin = "Origin: http://" + base.getHost() + ":" + base.getPort();
        RawHttp.Answer a = raw("GET /sensinact/providers HTTP/1.1\r\n" + RawHttp.host(base) + "\r\n" + origin
                + "\r\nOrigin: http://evil.example", null);
        assertError(a, 400, "2 Origin headers", "send one");
        // also with the acceptable one second
        a = raw("GET /sensinact/providers HTTP/1.1\r\n" + RawHttp.host(base) + "\r\nOrigin: http://evil.example\r\n"
                + origin, null);
        assertError(a, 400, "2 Origin headers");
        assertThat(raw("GET /sensinact/providers HTTP/1.1\r\n" + RawHttp.host(base) + "\r\n" + origin, null).status())
                .isEqualTo(200);
    }

    @Test
    void anUnknownPathIsNotEchoedWhole() throws Exception {
        String longName = "a".repeat(6_000);
        for (String path : List.of("/sensinact/" + longName, "/sensinact/providers/" + longName, "/" + longName)) {
            RawHttp.Answer a = raw("GET " + path + " HTTP/1.1\r\n" + RawHttp.host(base), null);
            assertError(a, 404, "characters)");
            assertThat(a.body().length()).as(path.substring(0, 30)).isLessThan(1_000);
        }
    }

    @Test
    void anInvalidAuthValueIsRefusedByNameAndTheApiStaysUpWithTheSafeDefault() throws Exception {
        configure(Map.of("auth", "none"));
        assertThat(get("/sensinact/providers").statusCode()).as("up, on loopback: no token needed").isEqualTo(200);
        assertThat(entries("auth='none' is not a value")).isNotEmpty().allSatisfy(e -> {
            assertThat(e.getLogLevel()).isEqualTo(LogLevel.ERROR);
            assertThat(e.getMessage()).contains("uses 'auto', the safe default");
        });
    }

    private static List<LogEntry> entries(String fragment) {
        List<LogEntry> found = new ArrayList<>();
        for (LogEntry e : Collections.list(logs.getLog())) {
            if (e.getMessage().contains(fragment)) {
                found.add(e);
            }
        }
        return found;
    }
}
