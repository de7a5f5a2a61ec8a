package eu.brain.iot.dashboard.browser;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.Optional;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.chrome.ChromeDriver;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.view.RobotView;

/**
 * The dashboard in headless Chromium against the real node (its own JVM, node/target/fabric-node.jar) polling an
 * embedded robot-sim over real HTTP. robot-sim steps only when the test says so, so that what the page must show is
 * known. Screenshots are saved under target/screenshots for a person to look at.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class DashboardBrowserTest {

    private static final Duration SHOWN = Duration.ofSeconds(30);
    private static final HttpClient HTTP = HttpClient.newHttpClient();

    @TempDir
    static Path home;

    private RobotSim sim;
    private Node node;
    private ChromeDriver driver;
    private DashboardPage page;

    @BeforeAll
    void start() throws Exception {
        Chromium.assumeInstalled();
        sim = RobotSim.start(SimConfig.builder().manualStep(true).build());
        // no behaviour repository: only the test's commands move robots, so what the page must show is known
        node = new Node(home.resolve("node"), sim.baseUri(), 100, false).start();
        driver = Chromium.start(home.resolve("chromium-profile"));
        page = new DashboardPage(driver);
        page.open(node.dashboard());
    }

    @AfterAll
    void stop() throws Exception {
        if (driver != null) {
            driver.quit();
        }
        if (node != null) {
            node.close();
        }
        if (sim != null) {
            sim.close();
        }
    }

    @Test
    @Order(1)
    void showsEachRobotWhereRobotSimHasItADoorsStateAndTheCounters() throws Exception {
        awaitPageShowsTheFleet();
        await("the page's stream live").atMost(SHOWN).until(() -> "live".equals(page.connection()));
        long sent = awaitCounter("commandsSent", c -> c >= 0);

        // a command through the node's REST API: counted, logged with its outcome, and the robot drawn as it moves
        act("robot1", "goTo", "{\"x\":9,\"y\":3}");
        awaitCounter("commandsSent", c -> c == sent + 1);
        await("the decision logged as accepted").atMost(SHOWN).until(() -> page.decisionOutcomes().contains("accepted"));
        sim.step(3);
        awaitPageShowsTheFleet();
        // robot1's way east along row 1 is blocked by robot2: robot-sim's robot1 sees a robot in front, so does the page
        assertThat(sim.robot("robot1").detect()).isEqualTo(1);
        awaitCounter("robotInFront", c -> c >= 1);

        // a door opened: drawn open, counted
        assertThat(page.door("door1").orElseThrow()).containsEntry("state", "closed");
        act("door1", "open", "{}");
        sim.step(6);
        await("door1 drawn open").atMost(SHOWN).until(() -> "open".equals(page.door("door1").orElseThrow().get("state")));
        awaitCounter("doorOpenings", c -> c == 1);

        // a command the robot refuses (a wall is no destination): counted as refused, logged as such
        act("robot2", "goTo", "{\"x\":0,\"y\":0}");
        awaitCounter("commandsRefused", c -> c == 1);
        await("the decision logged as refused").atMost(SHOWN).until(() -> page.decisionOutcomes().contains("refused"));

        sim.step(20);
        awaitPageShowsTheFleet();
        page.screenshot("1-fleet-door-counters");
    }

    @Test
    @Order(2)
    void showsAnUnreachableRobotAsSuchAndItsReturn() throws Exception {
        admin("POST", "admin/faults/robot2", "{\"offline\":true}");
        await("robot2 drawn as unreachable").atMost(SHOWN)
                .until(() -> "UNREACHABLE".equals(page.robot("robot2").orElseThrow().get("status")));
        assertThat(page.rowStatus("robot2")).contains("UNREACHABLE");
        assertThat(page.robot("robot1").orElseThrow()).containsEntry("status", "OK");
        page.screenshot("2-robot2-unreachable");

        admin("DELETE", "admin/faults", "");
        await("robot2 back").atMost(SHOWN)
                .until(() -> "OK".equals(page.robot("robot2").orElseThrow().get("status")));
        awaitPageShowsTheFleet();
    }

    @Test
    @Order(3)
    void reconnectsByItselfAfterTheNodeRestartsAndMissesNothing() throws Exception {
        awaitPageShowsTheFleet();
        String before = page.eventId();
        node.stop();
        await("the page sees the node gone").atMost(SHOWN).until(() -> !"live".equals(page.connection()));

        // the fleet moves while the node is down
        admin("POST", "robot3/robot_local_control/NavigationComponent/GoToComponent/add", "{\"x\":12,\"y\":3}");
        sim.step(4);
        RobotView moved = sim.robot("robot3");
        assertThat(moved.x() + "," + moved.y()).isNotEqualTo("6,1");

        node.start();
        await("the page live again").atMost(Node.START_DEADLINE).until(() -> "live".equals(page.connection()));
        awaitPageShowsTheFleet();
        assertThat(page.eventId()).as("a new node's events").isNotEqualTo(before)
                .doesNotStartWith(before.substring(0, before.indexOf('-') + 1));
        page.screenshot("3-after-node-restart");
    }

    /** Waits until the page draws every robot of robot-sim at the cell robot-sim has it on now. */
    private void awaitPageShowsTheFleet() {
        await("the page drawing every robot at robot-sim's cell").atMost(SHOWN).pollInterval(Duration.ofMillis(100))
                .until(() -> sim.robotIds().stream().allMatch(id -> {
                    RobotView r = sim.robot(id);
                    Optional<Map<String, Object>> drawn = page.robot(id);
                    return drawn.isPresent() && number(drawn.get().get("x")) == r.x()
                            && number(drawn.get().get("y")) == r.y() && r.heading().equals(drawn.get().get("heading"))
                            && r.state().equals(drawn.get().get("state"))
                            && number(drawn.get().get("detect")) == r.detect();
                }));
    }

    private long awaitCounter(String name, java.util.function.LongPredicate wanted) {
        await("counter " + name).atMost(SHOWN).pollInterval(Duration.ofMillis(100))
                .until(() -> wanted.test(page.counter(name)));
        return page.counter(name);
    }

    private void act(String device, String action, String body) throws Exception {
        node.post("sensinact/providers/" + device + "/services/control/resources/" + action + "/act", body);
    }

    private void admin(String method, String path, String body) throws IOException, InterruptedException {
        HttpRequest.Builder b = HttpRequest.newBuilder(sim.baseUri().resolve(path))
                .header("Content-Type", "application/json");
        b = method.equals("DELETE") ? b.DELETE() : b.POST(HttpRequest.BodyPublishers.ofString(body));
        HttpResponse<String> answer = HTTP.send(b.build(), HttpResponse.BodyHandlers.ofString());
        assertThat(answer.statusCode()).as(method + " " + path + ": " + answer.body()).isLessThan(300);
    }

    private static long number(Object o) {
        return o instanceof Number n ? n.longValue() : Long.MIN_VALUE;
    }
}
