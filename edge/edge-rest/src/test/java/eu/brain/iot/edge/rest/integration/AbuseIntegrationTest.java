package eu.brain.iot.edge.rest.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * Abusive clients on loopback, each phase bounded in count and time, and in each another client keeps getting its
 * answers (REST and SSE) within {@link #PATIENCE} while the abuse goes on.
 */
class AbuseIntegrationTest extends RestTestBase {

    /** How long a well-behaved client may wait for an answer while others abuse the API. */
    static final Duration PATIENCE = Duration.ofSeconds(5);
    private static final String ACT = "/sensinact/providers/door1/services/control/resources/open/act";

    /** Another client: reads, an ACT and a new SSE stream, each answered within {@link #PATIENCE}. */
    static void othersAreServed() throws Exception {
        HttpResponse<String> r = HTTP.send(HttpRequest.newBuilder(uri("/sensinact/providers")).timeout(PATIENCE).build(),
                HttpResponse.BodyHandlers.ofString());
        assertThat(r.statusCode()).isEqualTo(200);
        HttpResponse<String> act = HTTP.send(HttpRequest.newBuilder(uri(ACT)).timeout(PATIENCE)
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString("{}")).build(),
                HttpResponse.BodyHandlers.ofString());
        assertThat(act.statusCode()).as(act.body()).isEqualTo(200);
        HttpResponse<Stream<String>> sse = HTTP.send(HttpRequest.newBuilder(uri("/sensinact/subscribe?provider=door1"))
                .timeout(PATIENCE).build(), HttpResponse.BodyHandlers.ofLines());
        try (Stream<String> lines = sse.body()) {
            assertThat(sse.statusCode()).isEqualTo(200);
            assertThat(lines.findFirst()).hasValueSatisfying(l -> assertThat(l).startsWith(": subscribed"));
        }
    }

    /** The limits a test changed, back to their defaults. */
    @AfterEach
    void defaults() throws Exception {
        configure(Map.of("max.connections.per.client", 64, "act.body.timeout.ms", 10_000L));
    }

    private static String actHead(long contentLength) {
        return "POST " + ACT + " HTTP/1.1\r\n" + RawHttp.host(base) + "\r\nContent-Type: application/json\r\n"
                + "Content-Length: " + contentLength + "\r\n\r\n";
    }

    @Test
    void slowBodiesHoldNoThreadAndEndIn408() throws Exception {
        // the default per-client limit (64): the slow clients and the other one all connect from 127.0.0.1, as
        // every program on this machine does, and the other one is served all the same
        configure(Map.of("act.body.timeout.ms", 2_000L));
        List<Socket> slow = new ArrayList<>();
        try {
            for (int i = 0; i < 220; i++) { // more than Jetty's 200 threads
                Socket s = RawHttp.connect(base, null);
                slow.add(s);
                s.getOutputStream().write((actHead(1_000) + "{\"a\":").getBytes(StandardCharsets.UTF_8));
                s.getOutputStream().flush();
            }
            othersAreServed();
            // the body's deadline answers each of them 408 and closes its connection
            for (Socket s : slow) {
                RawHttp.Answer a = RawHttp.read(s.getInputStream());
                assertError(a, 408, "did not arrive within 2000 ms", "act.body.timeout.ms");
                assertThat(a.header("Connection")).isEqualTo("close");
            }
        } finally {
            for (Socket s : slow) {
                s.close();
            }
        }
        othersAreServed();
    }

    @Test
    void anOversizeDeclaredBodyIsRefusedAtOnce() throws Exception {
        try (Socket s = RawHttp.connect(base, null)) {
            // the headers alone, not a byte of the 100 MB: answered before any body arrives
            s.getOutputStream().write(actHead(100_000_000).getBytes(StandardCharsets.UTF_8));
            RawHttp.Answer a = RawHttp.read(s.getInputStream());
            assertError(a, 413, "larger than 65536 bytes", "act.max.body.bytes");
            assertThat(a.header("Connection")).isEqualTo("close");
            s.setSoTimeout(5_000);
            assertThat(s.getInputStream().read()).as("the connection closes").isEqualTo(-1);
        }
        othersAreServed();
    }

    @Test
    void oneClientCannotTakeEveryConnection() throws Exception {
        InetAddress other = InetAddress.getByName("127.0.0.2");
        try (Socket probe = new Socket()) {
            probe.bind(new java.net.InetSocketAddress(other, 0));
        } catch (IOException e) {
            Assumptions.abort("this machine cannot use 127.0.0.2 as a second loopback client: " + e);
        }
        configure(Map.of("max.connections.per.client", 8));
        List<Socket> hog = new ArrayList<>();
        try {
            for (int i = 0; i < 20; i++) {
                hog.add(RawHttp.connect(base, other));
            }
            await("the connections over 8 closed").atMost(DEADLINE).until(() -> closedCount(hog) == 12);
            othersAreServed(); // from 127.0.0.1
        } finally {
            for (Socket s : hog) {
                s.close();
            }
        }
    }

    /** How many of these connections the server closed (a read sees the end at once; an open one times out). */
    private static int closedCount(List<Socket> sockets) throws IOException {
        int closed = 0;
        for (Socket s : sockets) {
            s.setSoTimeout(20);
            try {
                InputStream in = s.getInputStream();
                if (in.read() < 0) {
                    closed++;
                }
            } catch (SocketTimeoutException e) {
                // still open
            } catch (IOException e) {
                closed++; // reset
            }
        }
        return closed;
    }

    @Test
    void badRequestsInALoopAreAnsweredAndLeaveOthersServed() throws Exception {
        String deep = "{\"x\":" + "[".repeat(5_000) + "]".repeat(5_000) + ",\"y\":1}";
        for (int i = 0; i < 30; i++) {
            assertError(raw("GET /sensinact/subscribe?provider=%ff" + i + " HTTP/1.1\r\n" + RawHttp.host(base), null),
                    400);
            assertError(post("/sensinact/providers/robot1/services/control/resources/goTo/act", deep), 400,
                    "nesting depth");
            assertError(raw("POST " + ACT + " HTTP/1.1\r\n" + RawHttp.host(base) + "\r\nOrigin: http://evil" + i
                    + ".example\r\nContent-Type: application/json\r\nContent-Length: 2", "{}"), 403);
            assertError(raw("GET /sensinact HTTP/1.1\r\nHost: rebound" + i + ".example", null), 421);
        }
        othersAreServed();
    }
}
