package eu.brain.iot.dashboard.browser;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.chrome.ChromeDriver;

import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;

/**
 * The dashboard behind the node's one gate (the edge's {@code AccessGate}) when the node requires its token, as it
 * does when exposed beyond loopback ({@code auth=token} forces it while the test stays on 127.0.0.1): its API answers
 * 401 without a token or session, works with the bearer token and with the session cookie from
 * {@code POST /sensinact/session} (the stream included), refuses a foreign Host or Origin; and a person logs in from
 * the page itself.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class DashboardAuthTest {

    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    static Path home;

    @AutoClose
    private RobotSim sim;
    @AutoClose
    private Node node;
    private String token;

    @BeforeAll
    void start() throws Exception {
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        Path tokenFile = home.resolve("token").resolve("api-token");
        node = new Node(home.resolve("node"), sim.baseUri(), 100, false).exposed(tokenFile).start();
        token = Files.readString(tokenFile).strip();
    }

    @Test
    void theApiNeedsTheTokenOrTheSessionCookieTheStreamIncluded() throws Exception {
        for (String path : new String[] { "dashboard/api/snapshot", "dashboard/api/stream" }) {
            HttpResponse<String> r = send(request(path));
            assertError(r, 401, "Authorization", "Authorization: Bearer");
            assertThat(r.headers().firstValue("WWW-Authenticate")).hasValueSatisfying(v -> assertThat(v)
                    .startsWith("Bearer"));
        }
        assertError(send(request("dashboard/api/snapshot").header("Cookie", "brain-iot-session=forged")), 401,
                "Authorization", null);
        // the page's files hold no data and must load to show the login form
        HttpResponse<String> page = send(request("dashboard/"));
        assertThat(page.statusCode()).isEqualTo(200);
        assertThat(page.body()).contains("id=\"login\"");

        assertThat(send(request("dashboard/api/snapshot").header("Authorization", "Bearer " + token)).statusCode())
                .isEqualTo(200);

        String cookie = session();
        HttpResponse<String> snapshot = send(request("dashboard/api/snapshot").header("Cookie", cookie));
        assertThat(snapshot.statusCode()).as(snapshot.body()).isEqualTo(200);
        assertThat(JSON.readTree(snapshot.body()).has("devices")).isTrue();

        HttpResponse<InputStream> stream = HTTP.send(request("dashboard/api/stream").header("Cookie", cookie).build(),
                HttpResponse.BodyHandlers.ofInputStream());
        try (BufferedReader lines = new BufferedReader(new InputStreamReader(stream.body(), StandardCharsets.UTF_8))) {
            assertThat(stream.statusCode()).isEqualTo(200);
            assertThat(stream.headers().firstValue("Content-Type").orElse("")).startsWith("text/event-stream");
            assertThat(lines.lines().filter(l -> l.startsWith("event:")).findFirst())
                    .hasValueSatisfying(l -> assertThat(l).contains("snapshot"));
        }
    }

    @Test
    void aForeignOriginOrHostIsRefused() throws Exception {
        String cookie = session();
        assertError(send(request("dashboard/api/snapshot").header("Cookie", cookie)
                .header("Origin", "http://evil.example")), 403, "Origin", "cross-origin");
        assertError(send(request("dashboard/").header("Origin", "http://evil.example")), 403, "Origin", null);
        // Host (DNS rebinding): java.net.http sets Host itself, so a raw request
        assertThat(raw("GET /dashboard/api/snapshot HTTP/1.1\r\nHost: evil.example\r\nCookie: " + cookie
                + "\r\nConnection: close\r\n\r\n")).startsWith("HTTP/1.1 421").contains("application/json")
                .contains("\"field\":\"Host\"");
        assertThat(raw("GET /dashboard/ HTTP/1.1\r\nHost: evil.example\r\nConnection: close\r\n\r\n"))
                .startsWith("HTTP/1.1 421");
    }

    @Test
    void aPersonLogsInFromThePage() throws Exception {
        Chromium.assumeInstalled();
        ChromeDriver driver = Chromium.start(home.resolve("chromium-profile"));
        try {
            DashboardPage page = new DashboardPage(driver);
            page.open(node.dashboard());
            await("the login form").atMost(Duration.ofSeconds(30))
                    .until(() -> driver.findElement(By.id("login")).isDisplayed());
            assertThat(page.connection()).isEqualTo("login");
            driver.findElement(By.id("login-token")).sendKeys("not-the-token");
            driver.findElement(By.cssSelector("#login button")).click();
            await("a wrong token refused").atMost(Duration.ofSeconds(30))
                    .until(() -> driver.findElement(By.id("login-error")).getText().contains("wrong token"));
            driver.findElement(By.id("login-token")).clear();
            driver.findElement(By.id("login-token")).sendKeys(token);
            driver.findElement(By.cssSelector("#login button")).click();
            await("the page live after logging in").atMost(Duration.ofSeconds(30))
                    .until(() -> "live".equals(page.connection()) && !page.robots().isEmpty());
            assertThat(driver.findElement(By.id("login")).isDisplayed()).isFalse();
            assertThat(driver.getCurrentUrl()).doesNotContain(token);
            page.screenshot("logged-in");
        } finally {
            driver.quit();
        }
    }

    @Test
    void theScreenshotEntryPointLogsInAndWaitsForTheDrawing() throws Exception {
        Chromium.assumeInstalled();
        Path out = DashboardPage.SCREENSHOTS.resolve("screenshot-entry-point.png");
        Files.deleteIfExists(out);
        assertThat(Screenshot.run(new String[] { node.dashboard().toString(), out.toString(), "--token-file",
                home.resolve("token").resolve("api-token").toString(), "--timeout-s", "60" })).isZero();
        assertThat(out).isNotEmptyFile();
        byte[] png = Files.readAllBytes(out);
        assertThat(new String(png, 1, 3, StandardCharsets.US_ASCII)).isEqualTo("PNG");
        // without the token: a screenshot of the login form, and a status that says the page is not live
        Path login = DashboardPage.SCREENSHOTS.resolve("screenshot-entry-point-login.png");
        assertThat(Screenshot.run(new String[] { node.dashboard().toString(), login.toString() })).isEqualTo(1);
        assertThat(login).isNotEmptyFile();
    }

    /** A session as a browser opens one: the token once, as a bearer token, with a JSON body. */
    private String session() throws Exception {
        HttpResponse<String> r = send(request("sensinact/session").header("Authorization", "Bearer " + token)
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString("{}")));
        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        String setCookie = r.headers().firstValue("Set-Cookie").orElseThrow();
        assertThat(setCookie).contains("Path=/;", "HttpOnly", "SameSite=Strict");
        return setCookie.substring(0, setCookie.indexOf(';'));
    }

    private HttpRequest.Builder request(String path) {
        return HttpRequest.newBuilder(node.base().resolve(path)).timeout(Duration.ofSeconds(10));
    }

    private static HttpResponse<String> send(HttpRequest.Builder request) throws Exception {
        return HTTP.send(request.build(), HttpResponse.BodyHandlers.ofString());
    }

    private static void assertError(HttpResponse<String> r, int status, String field, String saying) throws Exception {
        assertThat(JsonErrors.assertJsonError(r, status, saying).get("field").asText()).isEqualTo(field);
    }

    private String raw(String request) throws Exception {
        try (Socket socket = new Socket(node.base().getHost(), node.base().getPort())) {
            socket.setSoTimeout(10_000);
            OutputStream out = socket.getOutputStream();
            out.write(request.getBytes(StandardCharsets.US_ASCII));
            out.flush();
            return new String(socket.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
