package eu.brain.iot.edge.rest.integration;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * An exposed API requires the token: the test sets {@code auth=token}, which is what binding Felix HTTP to anything
 * but loopback does ({@code auth=auto}; the decision is unit-tested in RequestGateTest), with the token file in a
 * temporary folder. Without configuration (loopback) nothing is required: every other test class runs so.
 */
class AuthIntegrationTest extends RestTestBase {

    private static Path dir;

    private static Path tokenFile() throws Exception {
        if (dir == null) {
            dir = Files.createTempDirectory("edge-rest-auth");
        }
        return dir.resolve("brain-iot").resolve("test-node").resolve("api-token");
    }

    /** Back to loopback behaviour (auth=auto on a 127.0.0.1 bind) after each test. */
    @AfterEach
    void unexpose() throws Exception {
        configure(Map.of("auth", "auto"));
    }

    @AfterAll
    static void removeToken() throws Exception {
        if (dir != null) {
            try (Stream<Path> all = Files.walk(dir)) {
                all.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    private static void expose() throws Exception {
        configure(Map.of("auth", "token", "api.token.file", tokenFile().toString()));
    }

    private static HttpRequest.Builder request(String path) {
        return HttpRequest.newBuilder(uri(path)).timeout(Duration.ofSeconds(15));
    }

    @Test
    void exposedTheApiRequiresItsToken() throws Exception {
        assertThat(get("/sensinact/providers").statusCode()).as("loopback: no token needed").isEqualTo(200);
        expose();

        // generated at the first start that needs it, readable by its owner only
        Path file = tokenFile();
        assertThat(file).exists();
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(file))).isEqualTo("rw-------");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(file.getParent())))
                .isEqualTo("rwx------");
        String token = Files.readString(file).strip();
        assertThat(token).hasSizeGreaterThanOrEqualTo(32);

        HttpResponse<String> r = get("/sensinact/providers");
        assertThat(assertError(r, 401, "needs its token", "Authorization: Bearer", file.toString())
                .get("field").asText()).isEqualTo("Authorization");
        assertThat(r.headers().firstValue("WWW-Authenticate")).hasValueSatisfying(v -> assertThat(v).startsWith("Bearer"));
        assertError(HTTP.send(request("/sensinact/providers").header("Authorization", "Bearer wrong" + token).build(),
                HttpResponse.BodyHandlers.ofString()), 401);
        assertError(post("/sensinact/providers/door1/services/control/resources/open/act", "{}"), 401);
        assertError(HTTP.send(request("/sensinact/subscribe").build(), HttpResponse.BodyHandlers.ofString()), 401);

        HttpResponse<String> ok = HTTP.send(request("/sensinact/providers")
                .header("Authorization", "Bearer " + token).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(ok.statusCode()).as(ok.body()).isEqualTo(200);
        HttpResponse<String> act = HTTP.send(request("/sensinact/providers/door1/services/control/resources/open/act")
                .header("Authorization", "Bearer " + token).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString("{}")).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(act.statusCode()).as(act.body()).isEqualTo(200);

        // the same token at the next start: the file is kept
        configure(Map.of("session.max.age.s", 600L));
        assertThat(Files.readString(file).strip()).isEqualTo(token);
    }

    @Test
    void aBrowserSessionCookieWorksForTheStream() throws Exception {
        expose();
        String token = Files.readString(tokenFile()).strip();
        HttpResponse<String> session = HTTP.send(request("/sensinact/session")
                .header("Authorization", "Bearer " + token).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString("{}")).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(session.statusCode()).as(session.body()).isEqualTo(200);
        String setCookie = session.headers().firstValue("Set-Cookie").orElseThrow();
        assertThat(setCookie).startsWith("brain-iot-session=").contains("HttpOnly", "SameSite=Strict",
                "Path=/;");
        String cookie = setCookie.substring(0, setCookie.indexOf(';'));

        HttpResponse<Stream<String>> stream = HTTP.send(request("/sensinact/subscribe?provider=robot1")
                .header("Cookie", cookie).build(), HttpResponse.BodyHandlers.ofLines());
        try (Stream<String> lines = stream.body()) {
            assertThat(stream.statusCode()).isEqualTo(200);
            assertThat(lines.findFirst()).hasValueSatisfying(l -> assertThat(l).startsWith(": subscribed"));
        }
        assertThat(HTTP.send(request("/sensinact/providers").header("Cookie", cookie).build(),
                HttpResponse.BodyHandlers.ofString()).statusCode()).isEqualTo(200);
        assertError(HTTP.send(request("/sensinact/providers").header("Cookie", "brain-iot-session=forged").build(),
                HttpResponse.BodyHandlers.ofString()), 401);
        // a session needs the token: no session from nothing
        assertError(post("/sensinact/session", "{}"), 401);

        // logging out ends the session
        HttpResponse<String> out = HTTP.send(request("/sensinact/session").header("Cookie", cookie)
                .DELETE().build(), HttpResponse.BodyHandlers.ofString());
        assertThat(out.statusCode()).as(out.body()).isEqualTo(200);
        assertError(HTTP.send(request("/sensinact/providers").header("Cookie", cookie).build(),
                HttpResponse.BodyHandlers.ofString()), 401);
    }

    @Test
    void aTokenOthersCanReadIsRefused() throws Exception {
        expose();
        Path file = tokenFile();
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        try {
            configure(Map.of("session.max.age.s", 601L)); // a restart of the API, which reads the file again
            assertError(get("/sensinact/providers"), 503, "readable by other users", "chmod 600");
        } finally {
            Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
            configure(Map.of("session.max.age.s", 602L));
        }
        assertThat(get("/sensinact/providers").statusCode()).isEqualTo(401);
    }
}
