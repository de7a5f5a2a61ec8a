package eu.brain.iot.dashboard.browser;

import static org.awaitility.Awaitility.await;

import java.lang.management.ManagementFactory;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.chrome.ChromeDriver;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.world.MapGenerator;

/**
 * The page's cost with a large fleet, measured in the page: 1,000 robots moving in a generated 200 x 100 warehouse
 * (robot-sim, real time, a step every 500 ms), polled by the real node every 500 ms, shown in headless Chromium. The
 * page adds up, per second, the time it spent applying the events that arrived and drawing them
 * ({@code window.dashboard.perf}); this prints the distribution over the measured seconds. A benchmark, not a test:
 * it asserts nothing about time and runs only when asked:
 * <pre>
 * mvn -B -pl dashboard/browser-tests -am test-compile surefire:test -Dtest=DashboardBenchmark \
 *     -Dsurefire.failIfNoSpecifiedTests=false -Ddashboard.benchmark=true [-Ddashboard.benchmark.robots=1000]
 * </pre>
 */
@EnabledIfSystemProperty(named = "dashboard.benchmark", matches = "true")
class DashboardBenchmark {

    private static final int ROBOTS = Integer.getInteger("dashboard.benchmark.robots", 1_000);
    private static final int SECONDS = Integer.getInteger("dashboard.benchmark.seconds", 30);
    private static final int GOALS = 4;

    @TempDir
    Path home;

    @Test
    void measure() throws Exception {
        Chromium.assumeInstalled();
        try (RobotSim sim = RobotSim.start(SimConfig.builder()
                .map(MapGenerator.generate(200, 100, ROBOTS, 2 * ROBOTS, 5, 1)).build());
                Node node = new Node(home.resolve("node"), sim.baseUri(), 500, false).start()) {
            int goals = sendRobotsAround(sim);
            ChromeDriver driver = Chromium.start(home.resolve("profile"));
            try {
                DashboardPage page = new DashboardPage(driver);
                page.open(node.dashboard());
                await("the page showing every robot").atMost(Duration.ofSeconds(120))
                        .until(() -> page.robots().size() == ROBOTS);
                Thread.sleep(10_000); // warm-up: JIT of the page, the node and robot-sim; the benchmark's own pacing
                page.script("window.dashboard.perf.rasterise = true; window.dashboard.perf.seconds.length = 0;");
                Thread.sleep(SECONDS * 1_000L + 1_500);
                report(page, goals, page.screenshot("benchmark-" + ROBOTS + "-robots"));
            } finally {
                driver.quit();
            }
        }
    }

    /** Gives every robot a few goals on free corridor cells; returns how many were accepted. */
    private static int sendRobotsAround(RobotSim sim) throws Exception {
        HttpClient http = HttpClient.newHttpClient();
        JsonNode world = new ObjectMapper().readTree(http.send(HttpRequest.newBuilder(sim.baseUri().resolve("world"))
                .build(), HttpResponse.BodyHandlers.ofString()).body());
        List<int[]> free = new ArrayList<>();
        JsonNode rows = world.get("map");
        for (int y = 0; y < rows.size(); y++) {
            String row = rows.get(y).asText();
            for (int x = 0; x < row.length(); x++) {
                if (row.charAt(x) == '.') {
                    free.add(new int[] { x, y });
                }
            }
        }
        Random random = new Random(1);
        int accepted = 0;
        for (String robot : sim.robotIds()) {
            for (int i = 0; i < GOALS; i++) {
                int[] cell = free.get(random.nextInt(free.size()));
                URI add = sim.baseUri().resolve(robot + "/robot_local_control/NavigationComponent/GoToComponent/add");
                HttpResponse<Void> r = http.send(HttpRequest.newBuilder(add).header("Content-Type", "application/json")
                        .POST(HttpRequest.BodyPublishers.ofString("{\"x\":" + cell[0] + ",\"y\":" + cell[1] + "}"))
                        .build(), HttpResponse.BodyHandlers.discarding());
                accepted += r.statusCode() < 300 ? 1 : 0;
            }
        }
        return accepted;
    }

    @SuppressWarnings("unchecked")
    private static void report(DashboardPage page, int goals, Path screenshot) throws Exception {
        List<Map<String, Object>> seconds = (List<Map<String, Object>>) page.script(
                "return window.dashboard.perf.seconds.slice(0, " + SECONDS + ");");
        double[] total = seconds.stream().mapToDouble(s -> num(s.get("applyMs")) + num(s.get("drawMs"))).sorted()
                .toArray();
        double[] apply = seconds.stream().mapToDouble(s -> num(s.get("applyMs"))).sorted().toArray();
        double[] draw = seconds.stream().mapToDouble(s -> num(s.get("drawMs"))).sorted().toArray();
        double[] canvas = seconds.stream().mapToDouble(s -> num(s.get("canvasMs"))).sorted().toArray();
        double[] table = seconds.stream().mapToDouble(s -> num(s.get("tableMs"))).sorted().toArray();
        double[] panels = seconds.stream().mapToDouble(s -> num(s.get("panelsMs"))).sorted().toArray();
        double devices = seconds.stream().mapToDouble(s -> num(s.get("devices"))).average().orElse(0);
        double events = seconds.stream().mapToDouble(s -> num(s.get("events"))).average().orElse(0);
        double frames = seconds.stream().mapToDouble(s -> num(s.get("frames"))).average().orElse(0);
        String text = String.format(
                "dashboard benchmark: %d robots (%d goals accepted), %d s measured in the page%n"
                        + "  per second: %.0f events, %.0f robot changes, %.1f frames drawn%n"
                        + "  apply + draw per second (ms): median %.2f, p95 %.2f, max %.2f%n"
                        + "  apply (ms): median %.2f, max %.2f; draw (ms): median %.2f, max %.2f, of which (medians) canvas %.2f, device table %.2f, panels %.2f%n"
                        + "  machine: %d cores, load average %.2f, %s%n  screenshot: %s%n",
                ROBOTS, goals, total.length, events, devices, frames, pct(total, 0.5), pct(total, 0.95),
                pct(total, 1.0), pct(apply, 0.5), pct(apply, 1.0), pct(draw, 0.5), pct(draw, 1.0), pct(canvas, 0.5), pct(table, 0.5), pct(panels, 0.5),
                Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), cpu(), screenshot);
        System.out.print(text);
        Files.writeString(screenshot.resolveSibling("benchmark-" + ROBOTS + "-robots.txt"), text);
    }

    private static String cpu() {
        try {
            return Files.readAllLines(Path.of("/proc/cpuinfo")).stream().filter(l -> l.startsWith("model name"))
                    .findFirst().map(l -> l.substring(l.indexOf(':') + 1).trim()).orElse("cpu unknown");
        } catch (Exception e) {
            return "cpu unknown";
        }
    }

    private static double num(Object o) {
        return o instanceof Number n ? n.doubleValue() : 0;
    }

    private static double pct(double[] sorted, double p) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        return sorted[Math.min(sorted.length - 1, (int) Math.ceil(p * sorted.length) - 1 < 0 ? 0
                : (int) Math.ceil(p * sorted.length) - 1)];
    }
}
