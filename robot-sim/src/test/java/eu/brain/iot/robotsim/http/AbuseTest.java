package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import java.io.IOException;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A bounded abuse suite on loopback: slow bodies, bad queries and paths, deeply nested JSON, foreign origins and a
 * client that never reads its answers. Each phase is bounded in count (constants below) and time ({@link Timeout},
 * socket and client timeouts), and asserts that another client keeps getting its answers meanwhile and that the
 * abuser gets robot-sim's documented JSON error.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class AbuseTest {
    private static final int SLOW_CONNECTIONS = 100;
    private static final int BAD_TARGET_ROUNDS = 20;
    private static final int FLOOD = 200;
    private static final int WATCHDOG_POLLS = 40;
    private static final Duration ANSWER_WITHIN = Duration.ofSeconds(3);

    private RobotSim sim;
    private String host;
    private HttpClient abuser;
    private ExecutorService pool;

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).requestTimeoutMillis(1500).build());
        host = "Host: 127.0.0.1:" + sim.port();
        abuser = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1).build();
        pool = Executors.newFixedThreadPool(8);
    }

    @AfterEach
    void stop() {
        pool.shutdownNow();
        sim.close();
    }

    /** Another client, on its own connection, polls robot2 and must get every answer in time. */
    private void othersAreServed() throws Exception {
        HttpClient watchdog = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
                .connectTimeout(ANSWER_WITHIN).build();
        for (int i = 0; i < WATCHDOG_POLLS; i++) {
            HttpResponse<String> r = watchdog.send(HttpRequest.newBuilder(sim.robotStateUri("robot2"))
                    .timeout(ANSWER_WITHIN).build(), HttpResponse.BodyHandlers.ofString());
            assertThat(r.statusCode()).isEqualTo(200);
            assertThat(Client.JSON.readTree(r.body()).get("id").asText()).isEqualTo("robot2");
        }
    }

    private static void assertJsonError(int status, String contentType, String body, int expected, String start)
            throws IOException {
        assertThat(status).as(body).isEqualTo(expected);
        assertThat(contentType).isEqualTo("application/json");
        JsonNode error = Client.JSON.readTree(body);
        assertThat(error.get("status").asInt()).isEqualTo(expected);
        assertThat(error.get("error").asText()).startsWith(start);
    }

    private void assertWorldUntouched() {
        long step = sim.inspect(w -> w.step());
        assertThat(step).isZero();
        for (String robot : sim.robotIds()) {
            assertThat(sim.robot(robot).mission()).as(robot).isNull();
        }
        assertThat(sim.door("door1").state()).isEqualTo("closed");
        assertThat(sim.faults().fleet().offline()).isFalse();
    }

    @Test
    void slowBodiesHoldNoOneUpAndEndIn408() throws Exception {
        List<RawHttp> slow = new ArrayList<>();
        try {
            for (int i = 0; i < SLOW_CONNECTIONS; i++) {
                RawHttp c = new RawHttp(sim.port(), 15_000);
                slow.add(c);
                c.send("POST /admin/step HTTP/1.1\r\n" + host + "\r\nContent-Type: application/json\r\n"
                        + "Content-Length: 1000\r\n\r\n{\"steps\":");
            }
            othersAreServed();
            for (RawHttp c : slow) {
                RawHttp.Answer a = c.read();
                assertJsonError(a.status(), a.headers().get("content-type"), a.body(), 408,
                        "the request did not arrive whole within 1500 ms");
                assertThat(c.closedByServer()).isTrue();
            }
        } finally {
            for (RawHttp c : slow) {
                c.close();
            }
        }
        othersAreServed();
        assertWorldUntouched();
    }

    @Test
    void badQueriesAndPathsGetJsonAnswers() throws Exception {
        String[] targets = {"/robot1/robot_local_control/state?%ff", "/robot1/robot_local_control/state?p=%C0%AF",
            "/%ff/robot_local_control/state", "/%C0%AF", "/..%2f..%2fetc%2fpasswd", "/robot1/../admin/faults",
            "/world?" + "a=&".repeat(900), "/robot1/robot_local_control/state?%", "/admin/faults/%00",
            "/robot1/robot_local_control/NavigationComponent/GoToComponent/query_state?x=%00%ff",
            "/door1/door_controller/state;jsessionid=x", "*", "/%2e%2e/%2e%2e/world"};
        CompletableFuture<Void> abuse = CompletableFuture.runAsync(() -> {
            try (RawHttp c = new RawHttp(sim.port())) {
                for (int round = 0; round < BAD_TARGET_ROUNDS; round++) {
                    for (String target : targets) {
                        RawHttp.Answer a = c.send(RawHttp.request("GET", target, null, host)).read();
                        assertThat(a.status()).as(target).isIn(200, 404);
                        assertThat(a.headers().get("content-type")).isEqualTo("application/json");
                        JsonNode body = a.json();
                        if (a.status() != 200) {
                            assertThat(body.get("status").asInt()).isEqualTo(a.status());
                            assertThat(body.get("error").asText()).isNotBlank();
                        }
                    }
                }
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        }, pool);
        othersAreServed();
        abuse.get(60, TimeUnit.SECONDS);
        assertWorldUntouched();
    }

    /** Sends {@link #FLOOD} requests from 8 threads; waits until some were answered, then checks the others. */
    private void flood(java.util.function.IntFunction<HttpRequest> request, int status, String errorStart)
            throws Exception {
        AtomicInteger answered = new AtomicInteger();
        List<CompletableFuture<Void>> all = new ArrayList<>();
        for (int t = 0; t < 8; t++) {
            int thread = t;
            all.add(CompletableFuture.runAsync(() -> {
                for (int i = thread; i < FLOOD; i += 8) {
                    try {
                        HttpResponse<String> r = abuser.send(request.apply(i), HttpResponse.BodyHandlers.ofString());
                        assertJsonError(r.statusCode(), r.headers().firstValue("Content-Type").orElse(null),
                                r.body(), status, errorStart);
                        answered.incrementAndGet();
                    } catch (IOException e) {
                        throw new IllegalStateException(e);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return;
                    }
                }
            }, pool));
        }
        await("the flood is under way").atMost(Duration.ofSeconds(30)).until(() -> answered.get() >= 10);
        othersAreServed();
        CompletableFuture.allOf(all.toArray(CompletableFuture[]::new)).get(60, TimeUnit.SECONDS);
        assertThat(answered.get()).isEqualTo(FLOOD);
        assertWorldUntouched();
    }

    @Test
    void deeplyNestedJsonFloodIsRefused() throws Exception {
        String deep = BadInputTest.deepJson(5000);
        flood(i -> HttpRequest.newBuilder(sim.baseUri().resolve(
                        BadInputTest.POST_ENDPOINTS[i % BadInputTest.POST_ENDPOINTS.length]))
                .header("Content-Type", "application/json").timeout(Duration.ofSeconds(20))
                .POST(HttpRequest.BodyPublishers.ofString(deep)).build(), 400, "JSON nesting depth exceeds 16");
    }

    @Test
    void foreignOriginsChangeNothing() throws Exception {
        String[][] orders = {
            {"robot1/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":6,\"y\":4}"},
            {"door1/door_controller/command", "{\"data\":1.0}"},
            {"admin/faults", "{\"offline\":true}"},
            {"admin/step", "{\"steps\":100}"},
        };
        flood(i -> HttpRequest.newBuilder(sim.baseUri().resolve(orders[i % orders.length][0]))
                .headers("Content-Type", "application/json", "Origin", "http://evil" + i + ".example")
                .timeout(Duration.ofSeconds(20))
                .POST(HttpRequest.BodyPublishers.ofString(orders[i % orders.length][1])).build(), 403,
                "cross-origin request refused");
    }

    @Test
    void aClientThatNeverReadsItsAnswersHoldsNoOneUp() throws Exception {
        RawHttp greedy = new RawHttp(sim.port());
        String burst = RawHttp.request("GET", "/world", null, host).repeat(500);
        CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
            try {
                for (int i = 0; i < 40; i++) { // 20,000 requests, ~30 MB of answers nobody reads
                    greedy.send(burst);
                }
            } catch (IOException e) {
                // closed below while blocked: robot-sim stopped reading, as it should
            }
        }, pool);
        othersAreServed();
        greedy.close();
        writer.get(30, TimeUnit.SECONDS);
        othersAreServed();
        assertWorldUntouched();
    }
}
