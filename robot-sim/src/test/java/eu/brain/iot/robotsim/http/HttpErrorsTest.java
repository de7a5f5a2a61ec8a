package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * What the HTTP layer refuses before an endpoint sees the request answers robot-sim's JSON error too, and HEAD
 * works wherever GET does.
 */
class HttpErrorsTest {
    private static final String JSON = "Content-Type: application/json";
    private RobotSim sim;
    private String host;

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).requestTimeoutMillis(500).build());
        host = "Host: 127.0.0.1:" + sim.port();
    }

    @AfterEach
    void stop() {
        sim.close();
    }

    private static void assertJsonError(RawHttp.Answer a, int status, String errorStart) {
        assertThat(a.status()).isEqualTo(status);
        assertThat(a.headers().get("content-type")).isEqualTo("application/json");
        JsonNode error = a.json();
        assertThat(error.get("status").asInt()).isEqualTo(status);
        assertThat(error.get("error").asText()).startsWith(errorStart);
    }

    @Test
    void aDeclaredBodyOverTheLimitIs413AtOnce() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send("POST /admin/step HTTP/1.1\r\n" + host + "\r\n" + JSON + "\r\nContent-Length: 100000\r\n\r\n");
            RawHttp.Answer a = c.read();
            assertJsonError(a, 413, "the body is too large: Content-Length 100000 > 65536 bytes");
            assertThat(a.headers().get("connection")).isEqualTo("close");
            assertThat(c.closedByServer()).isTrue();
        }
    }

    @Test
    void aChunkedBodyOverTheLimitIs413() throws Exception {
        String chunk = "{" + " ".repeat(40_000);
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send("POST /admin/step HTTP/1.1\r\n" + host + "\r\n" + JSON + "\r\nTransfer-Encoding: chunked\r\n\r\n"
                    + Integer.toHexString(chunk.length()) + "\r\n" + chunk + "\r\n"
                    + Integer.toHexString(chunk.length()) + "\r\n" + chunk + "\r\n0\r\n\r\n");
            assertJsonError(c.read(), 413, "the body is too large: more than 65536 bytes");
        }
    }

    @Test
    void expectContinueIsAnsweredOrRefusedInJson() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send("POST /admin/step HTTP/1.1\r\n" + host + "\r\n" + JSON
                    + "\r\nExpect: 100-continue\r\nContent-Length: 12\r\n\r\n");
            assertThat(c.read(true).status()).isEqualTo(100);
            c.send("{\"steps\":2}\n");
            assertThat(c.read().json().get("step").asLong()).isEqualTo(2);
            c.send("POST /admin/step HTTP/1.1\r\n" + host + "\r\n" + JSON
                    + "\r\nExpect: 100-continue\r\nContent-Length: 70000\r\n\r\n");
            assertJsonError(c.read(), 413, "the body is too large");
        }
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send("POST /admin/step HTTP/1.1\r\n" + host + "\r\n" + JSON
                    + "\r\nExpect: a-miracle\r\nContent-Length: 2\r\n\r\n");
            assertJsonError(c.read(), 417, "unsupported Expect: a-miracle (only 100-continue)");
        }
    }

    @Test
    void aTooLongRequestLineIs414() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send("GET /" + "a".repeat(5000) + " HTTP/1.1\r\n" + host + "\r\n\r\n");
            assertJsonError(c.read(), 414, "the request line is too long (at most 4096 bytes");
        }
    }

    @Test
    void tooLargeHeadersAre431() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send("GET /world HTTP/1.1\r\n" + host + "\r\nX-Big: " + "b".repeat(9000) + "\r\n\r\n");
            assertJsonError(c.read(), 431, "the request headers are too large (at most 8192 bytes)");
        }
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"HELLO\r\n\r\n", "GET /world HTTP/1.1\r\nno colon here\r\n\r\n",
        "POST /admin/step HTTP/1.1\r\nContent-Length: 2\r\nContent-Length: 3\r\n\r\n{}",
        "POST /admin/step HTTP/1.1\r\nContent-Length: -4\r\n\r\n"})
    void aMalformedRequestIs400(String request) throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(request);
            RawHttp.Answer a = c.read();
            assertJsonError(a, 400, "malformed HTTP request: ");
            assertThat(c.closedByServer()).isTrue();
        }
    }

    @Test
    void aRequestThatDoesNotArriveInTimeIs408() throws Exception {
        try (RawHttp slowBody = new RawHttp(sim.port()); RawHttp slowHead = new RawHttp(sim.port())) {
            slowBody.send("POST /admin/step HTTP/1.1\r\n" + host + "\r\n" + JSON + "\r\nContent-Length: 12\r\n\r\n{\"st");
            slowHead.send("GET /world HTTP/1.1\r\nHo");
            for (RawHttp c : new RawHttp[] {slowBody, slowHead}) {
                RawHttp.Answer a = c.read();
                assertJsonError(a, 408, "the request did not arrive whole within 500 ms");
                assertThat(c.closedByServer()).isTrue();
            }
        }
        long step = sim.inspect(w -> w.step());
        assertThat(step).as("the cut-off step request did nothing").isZero();
    }

    @Test
    void anIdleKeepAliveConnectionIsNotTimedOut() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            assertThat(c.send(RawHttp.request("GET", "/world/counters", null, host)).read().status()).isEqualTo(200);
            await("no 408 on an idle connection").during(Duration.ofMillis(1200)).atMost(Duration.ofSeconds(5))
                    .until(() -> c.available() == 0);
            assertThat(c.send(RawHttp.request("GET", "/world/counters", null, host)).read().status()).isEqualTo(200);
        }
    }

    @ParameterizedTest(name = "HEAD {0}")
    @ValueSource(strings = {"/", "/world", "/world/counters", "/robot1/robot_local_control/state",
        "/door1/door_controller/state", "/admin/faults", "/admin/faults/robot2",
        "/robot1/robot_local_control/NavigationComponent/GoToComponent/query_state", "/robot9/robot_local_control/state"})
    void headAnswersWhatGetWouldWithoutTheBody(String path) throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(RawHttp.request("GET", path, null, host) + RawHttp.request("HEAD", path, null, host)
                    + RawHttp.request("GET", "/robot2/robot_local_control/state", null, host));
            RawHttp.Answer get = c.read();
            RawHttp.Answer head = c.read(true);
            assertThat(head.status()).isEqualTo(get.status());
            assertThat(head.headers()).isEqualTo(get.headers());
            assertThat(head.body()).isEmpty();
            assertThat(c.read().json().get("id").asText()).as("no body came after the HEAD answer")
                    .isEqualTo("robot2");
        }
    }

    @Test
    void headWhereOnlyPostIsAllowedIs405() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            RawHttp.Answer a = c.send(RawHttp.request("HEAD", "/admin/step", null, host)).read(true);
            assertThat(a.status()).isEqualTo(405);
            assertThat(a.headers().get("allow")).isEqualTo("POST");
            RawHttp.Answer get = c.send(RawHttp.request("PUT", "/world", "{}", host, JSON)).read();
            assertJsonError(get, 405, "PUT is not allowed on /world (use GET, HEAD)");
            assertThat(get.headers().get("allow")).isEqualTo("GET, HEAD");
        }
    }
}
