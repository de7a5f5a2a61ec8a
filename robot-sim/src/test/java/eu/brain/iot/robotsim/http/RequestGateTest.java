package eu.brain.iot.robotsim.http;

import static org.assertj.core.api.Assertions.assertThat;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import java.net.http.HttpRequest;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Requests a web page could make: state changes need {@code Content-Type: application/json}, a foreign
 * {@code Origin} is refused, and {@code Host} must be a name of this server (DNS rebinding). Refused requests change
 * nothing.
 */
class RequestGateTest {
    private RobotSim sim;
    private Client client;

    @BeforeEach
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).allowHost("Robots.Example").build());
        client = new Client(sim.baseUri());
    }

    @AfterEach
    void stop() {
        sim.close();
    }

    private Client.Answer post(String path, String body, String... headers) throws Exception {
        HttpRequest.Builder b = HttpRequest.newBuilder(sim.baseUri().resolve(path))
                .POST(HttpRequest.BodyPublishers.ofString(body));
        if (headers.length > 0) {
            b.headers(headers);
        }
        return client.send(b);
    }

    /** Every state change robot-sim has: method and path. */
    private static List<String[]> stateChanges() {
        List<String[]> all = new ArrayList<>();
        for (String path : BadInputTest.POST_ENDPOINTS) {
            all.add(new String[] {"POST", path});
        }
        all.add(new String[] {"DELETE", "admin/faults"});
        all.add(new String[] {"DELETE", "admin/faults/robot1"});
        return all;
    }

    @ParameterizedTest(name = "Content-Type {0}")
    @ValueSource(strings = {"", "text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x",
        "application/jsonx", "text/json"})
    void everyStateChangeNeedsApplicationJson(String type) throws Exception {
        for (String[] change : stateChanges()) {
            HttpRequest.Builder b = HttpRequest.newBuilder(sim.baseUri().resolve(change[1]))
                    .method(change[0], HttpRequest.BodyPublishers.ofString(change[0].equals("POST")
                            ? body(change[1]) : ""));
            if (!type.isEmpty()) {
                b.header("Content-Type", type);
            }
            Client.Answer a = client.send(b);
            assertThat(a.status()).as(change[0] + " " + change[1]).isEqualTo(415);
            assertThat(a.json().get("field").asText()).isEqualTo("Content-Type");
            assertThat(a.json().get("error").asText()).as(change[1])
                    .startsWith(change[0] + " needs Content-Type: application/json, found "
                            + (type.isEmpty() ? "none" : "'" + type + "'"))
                    .endsWith("(with curl: -H 'Content-Type: application/json')");
        }
        assertNothingChanged();
    }

    /** A body each endpoint would accept. */
    private static String body(String path) {
        if (path.endsWith("GoToComponent/add")) {
            return "{\"x\":6,\"y\":4}";
        }
        if (path.endsWith("command")) {
            return "{\"data\":1.0}";
        }
        if (path.startsWith("admin/faults")) {
            return "{\"offline\":true}";
        }
        return "{}";
    }

    private void assertNothingChanged() throws Exception {
        assertThat(client.get("world/counters").json().get("step").asLong()).as("no step").isZero();
        for (String robot : sim.robotIds()) {
            assertThat(sim.robot(robot).mission()).as(robot + " got no mission").isNull();
        }
        assertThat(sim.door("door1").state()).isEqualTo("closed");
        assertThat(client.get("admin/faults").json().get("robots").isEmpty()).as("no fault set").isTrue();
        assertThat(client.get("admin/faults").json().get("fleet").get("offline").asBoolean()).isFalse();
    }

    @Test
    void jsonWithACharsetIsFine() throws Exception {
        Client.Answer a = post("door1/door_controller/command", "{\"data\":1.0}",
                "Content-Type", "Application/JSON; charset=utf-8");
        assertThat(a.status()).isEqualTo(200);
        assertThat(sim.door("door1").state()).isEqualTo("opening");
    }

    @ParameterizedTest(name = "Origin {0}")
    @ValueSource(strings = {"http://evil.example", "null", "http://127.0.0.1", "http://127.0.0.1:1",
        "https://127.0.0.1:PORT", "http://127.0.0.1.evil.example:PORT", "http://localhost:PORT/path",
        "file://", "http://robots.example.evil:PORT"})
    void aForeignOriginIsRefusedForReadsAndWrites(String origin) throws Exception {
        String o = origin.replace("PORT", Integer.toString(sim.port()));
        for (String[] change : stateChanges()) {
            Client.Answer a = client.send(HttpRequest.newBuilder(sim.baseUri().resolve(change[1]))
                    .headers("Origin", o, "Content-Type", "application/json")
                    .method(change[0], HttpRequest.BodyPublishers.ofString(change[0].equals("POST")
                            ? body(change[1]) : "")));
            assertThat(a.status()).as(change[0] + " " + change[1]).isEqualTo(403);
            assertThat(a.json().get("field").asText()).isEqualTo("Origin");
            assertThat(a.json().get("error").asText()).startsWith("cross-origin request refused: Origin '" + o
                    + "' is not this server (accepted: no Origin, or http:// and one of 127.0.0.1:" + sim.port());
        }
        Client.Answer read = client.send(HttpRequest.newBuilder(sim.baseUri().resolve("world")).header("Origin", o));
        assertThat(read.status()).isEqualTo(403);
        assertNothingChanged();
    }

    @ParameterizedTest(name = "Origin {0}")
    @ValueSource(strings = {"http://127.0.0.1:PORT", "http://localhost:PORT", "http://LOCALHOST:PORT",
        "http://[::1]:PORT", "http://robots.example:PORT"})
    void theServersOwnOriginsAreFine(String origin) throws Exception {
        String o = origin.replace("PORT", Integer.toString(sim.port()));
        assertThat(post("door1/door_controller/command", "{\"data\":1.0}", "Origin", o,
                "Content-Type", "application/json").status()).isEqualTo(200);
        assertThat(client.send(HttpRequest.newBuilder(sim.baseUri().resolve("world")).header("Origin", o)).status())
                .isEqualTo(200);
    }

    @ParameterizedTest(name = "Host {0}")
    @ValueSource(strings = {"evil.example:PORT", "evil.example", "127.0.0.1", "127.0.0.1:1", "localhost:PORT0",
        "127.0.0.2:PORT", "[::2]:PORT", "robots.example.evil:PORT", "127.0.0.1:PORT:PORT", "127.0.0.1:x"})
    void aHostThatIsNotThisServerIsRefused(String host) throws Exception {
        String h = host.replace("PORT", Integer.toString(sim.port()));
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(RawHttp.request("GET", "/robot1/robot_local_control/state", null, "Host: " + h));
            c.send(RawHttp.request("POST", "/door1/door_controller/command", "{\"data\":1.0}", "Host: " + h,
                    "Content-Type: application/json"));
            for (int i = 0; i < 2; i++) {
                RawHttp.Answer a = c.read();
                assertThat(a.status()).isEqualTo(421);
                assertThat(a.headers().get("content-type")).isEqualTo("application/json");
                assertThat(a.json().get("field").asText()).isEqualTo("Host");
                assertThat(a.json().get("error").asText()).isEqualTo("Host '" + h + "' is not a name of this server"
                        + " (accepted: 127.0.0.1:" + sim.port() + ", [::1]:" + sim.port() + ", localhost:" + sim.port()
                        + ", robots.example:" + sim.port() + "; robot-sim's --allow-host NAME adds one)");
            }
        }
        assertThat(sim.door("door1").state()).isEqualTo("closed");
    }

    @ParameterizedTest(name = "Host {0}")
    @ValueSource(strings = {"127.0.0.1:PORT", "localhost:PORT", "LocalHost:PORT", "[::1]:PORT",
        "robots.example:PORT", "ROBOTS.EXAMPLE:PORT"})
    void theConfiguredHostNamesAreFine(String host) throws Exception {
        String h = host.replace("PORT", Integer.toString(sim.port()));
        try (RawHttp c = new RawHttp(sim.port())) {
            c.send(RawHttp.request("GET", "/robot1/robot_local_control/state", null, "Host: " + h));
            assertThat(c.read().json().get("id").asText()).isEqualTo("robot1");
        }
    }

    @Test
    void http11NeedsAHostAndOneOnly() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            RawHttp.Answer a = c.send(RawHttp.request("GET", "/world/counters", null)).read();
            assertThat(a.status()).isEqualTo(400);
            assertThat(a.json().get("error").asText()).startsWith("missing Host header");
            String host = "Host: 127.0.0.1:" + sim.port();
            a = c.send(RawHttp.request("GET", "/world/counters", null, host, host)).read();
            assertThat(a.status()).isEqualTo(400);
            assertThat(a.json().get("error").asText()).isEqualTo("more than one Host header");
        }
        try (RawHttp c = new RawHttp(sim.port())) {
            RawHttp.Answer a = c.send("GET /world/counters HTTP/1.0\r\n\r\n").read();
            assertThat(a.status()).as("HTTP/1.0 has no Host").isEqualTo(200);
        }
    }

    @Test
    void refusedRequestsKeepTheConnection() throws Exception {
        try (RawHttp c = new RawHttp(sim.port())) {
            String host = "Host: 127.0.0.1:" + sim.port();
            c.send(RawHttp.request("POST", "/admin/step", "{}", host));
            c.send(RawHttp.request("POST", "/admin/step", "{}", host, "Origin: http://evil.example",
                    "Content-Type: application/json"));
            c.send(RawHttp.request("POST", "/admin/step", "{}", "Host: evil.example",
                    "Content-Type: application/json"));
            c.send(RawHttp.request("POST", "/admin/step", "{}", host, "Content-Type: application/json"));
            assertThat(c.read().status()).isEqualTo(415);
            assertThat(c.read().status()).isEqualTo(403);
            assertThat(c.read().status()).isEqualTo(421);
            assertThat(c.read().json().get("step").asLong()).as("only the last one stepped").isEqualTo(1);
        }
    }
}
