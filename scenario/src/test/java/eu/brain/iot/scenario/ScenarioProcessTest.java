package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The runner as a user runs it, with the real node (node/target/fabric-node.jar, its own JVM) and robot-sim, but
 * without a behaviour repository, so that nothing drives the robots: the run ends at its deadline (a few warehouse
 * seconds), fails with what was missing, writes its report, and leaves neither the node nor robot-sim running.
 */
class ScenarioProcessTest {
    private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();

    @Test
    void behavioursThatDoNothingFailAtTheDeadlineAndBothProcessesAreStopped(@TempDir Path run) throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"--root", ROOT.toString(), "--no-behaviours", "--deadline", "0.1",
                "--speed", "20", "--progress", "0.2", "--run-dir", run.toString(),
                "--fault-offline", "robot2@1s+2s"}, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        String text = out.toString(StandardCharsets.UTF_8);
        assertThat(err.toString(StandardCharsets.UTF_8)).as(text).isEmpty();
        assertThat(code).as(text).isEqualTo(1);
        assertThat(text).contains("its edge sees the fleet; wait limit 10.0 s")
                .containsPattern("\\[ +\\d+\\.\\d s\\] carts 0/3 delivered \\| door openings 0 \\|")
                .contains("fault: robot2 goes offline", "fault: robot2 is back online")
                .contains("FAIL  REQ-1 every cart lifted and carried to storage: 0/3 carts in storage; not delivered: "
                        + "cart1 at (3,7), cart2 at (10,7), cart3 at (16,7)")
                .contains("FAIL  every command accepted or its refusal handled: no command reached the fleet")
                .containsPattern("FAIL  finished before the deadline: the deadline ended the run at [0-9.]+ s of warehouse time")
                .contains("scenario FAILED")
                .doesNotContain("Exception");

        JsonNode report = ReportWriter.MAPPER.readTree(run.resolve("report.json").toFile());
        assertThat(report.path("passed").asBoolean(true)).isFalse();
        assertThat(report.path("warehouse").path("robots").asInt()).isEqualTo(3);
        assertThat(report.path("figures").path("warehouseSeconds").asDouble()).as("the deadline").isGreaterThanOrEqualTo(6.0);
        assertThat(report.path("figures").path("warehouseSecondsUntilAllDelivered").isNull()).isTrue();
        assertThat(report.path("figures").path("nodeCpuSeconds").asDouble()).isPositive();
        assertThat(report.path("figures").has("busEventsPerSecond")).isTrue();
        assertThat(report.path("faults")).hasSize(2);
        assertThat(Files.readString(run.resolve("node.log"))).contains("fabric node ready in ");
        assertThat(Files.readString(run.resolve("node-config/eu.brain.iot.edge.cfg")))
                .contains("poll.period.ms=13", "fleet.url=http://127.0.0.1:");
        assertThat(run.resolve("node-config/eu.brain.iot.bis.cfg")).as("no repository: no installer").doesNotExist();

        long nodePid = Long.parseLong(find(text, "node: pid (\\d+)"));
        Optional<ProcessHandle> node = ProcessHandle.of(nodePid);
        assertThat(node.map(ProcessHandle::isAlive).orElse(false)).as("the node's JVM is stopped").isFalse();
        int simPort = Integer.parseInt(find(text, "at http://127\\.0\\.0\\.1:(\\d+)/"));
        assertThat(listening(simPort)).as("robot-sim is closed").isFalse();
    }

    @Test
    void aWarehouseWithMoreCartsThanItsRobotsMayLiftIsRefusedBeforeAnythingStarts(@TempDir Path run) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"--root", ROOT.toString(), "--generate", "--width", "60", "--height", "30",
                "--robots", "10", "--carts", "31", "--run-dir", run.toString()},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertThat(code).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("has 31 carts, but its 10 robots can move at most 30")
                .contains("Use at least 11 robots or at most 30 carts");
        assertThat(out.toString(StandardCharsets.UTF_8)).as("nothing started").doesNotContain("robot-sim:");
    }

    /**
     * The success path, with the test in the behaviours' place: once the run has started, the test sends robot3's
     * errands through the node's edge (its REST API's ACT endpoints, which command robot-sim), and the run ends by
     * itself when every cart is in storage and robot3 is back, with exit 0 and the figures in the report.
     */
    @Test
    void aRunDrivenThroughTheEdgeEndsByItselfAndPasses(@TempDir Path run) throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(out, true, StandardCharsets.UTF_8);
        java.util.concurrent.CompletableFuture<Integer> code = java.util.concurrent.CompletableFuture.supplyAsync(
                () -> Main.run(new String[] {"--root", ROOT.toString(), "--no-behaviours", "--deadline", "10",
                        "--speed", "20", "--run-dir", run.toString()}, print, print));
        org.awaitility.Awaitility.await("the run's start").atMost(java.time.Duration.ofSeconds(150))
                .until(() -> out.toString(StandardCharsets.UTF_8).contains("its edge sees the fleet") || code.isDone());
        String started = out.toString(StandardCharsets.UTF_8);
        assertThat(started).contains("its edge sees the fleet");
        URI edge = URI.create(find(started, "REST API (http://127\\.0\\.0\\.1:\\d+/sensinact)") + "/providers/");
        act(edge, "door1", "open", "{}");
        int[][] carts = {{3, 7}, {10, 7}, {16, 7}};
        int[][] storage = {{12, 2}, {14, 2}, {16, 2}};
        for (int i = 0; i < carts.length; i++) {
            act(edge, "robot3", "goTo", "{\"x\":" + carts[i][0] + ",\"y\":" + carts[i][1] + "}");
            act(edge, "robot3", "pick", "{}");
            act(edge, "robot3", "goTo", "{\"x\":" + storage[i][0] + ",\"y\":" + storage[i][1] + "}");
            act(edge, "robot3", "place", "{}");
        }
        act(edge, "robot3", "goTo", "{\"x\":6,\"y\":1}");
        int exit = code.get(150, java.util.concurrent.TimeUnit.SECONDS);
        String text = out.toString(StandardCharsets.UTF_8);
        assertThat(exit).as(text).isZero();
        assertThat(text).contains("carts 3/3 delivered", "scenario PASSED",
                "PASS  REQ-1 every cart lifted and carried to storage: 3/3 carts in storage",
                "PASS  every command accepted or its refusal handled: 14 accepted, 0 refused");
        JsonNode figures = ReportWriter.MAPPER.readTree(run.resolve("report.json").toFile()).path("figures");
        assertThat(figures.path("warehouseSecondsUntilAllDelivered").asDouble()).isPositive();
        assertThat(figures.path("cartsPerWarehouseHour").asDouble()).isPositive();
        assertThat(figures.path("doorOpenings").asInt()).isEqualTo(1);
        assertThat(figures.path("commandsAccepted").asInt()).isEqualTo(14);
        long nodePid = Long.parseLong(find(text, "node: pid (\\d+)"));
        assertThat(ProcessHandle.of(nodePid).map(ProcessHandle::isAlive).orElse(false)).isFalse();
    }

    /** An ACT through the edge's REST API; it answers 200 when the fleet accepted the command. */
    private static void act(URI providers, String device, String action, String body) throws Exception {
        java.net.http.HttpResponse<String> answer = java.net.http.HttpClient.newHttpClient().send(
                java.net.http.HttpRequest.newBuilder(providers.resolve(device + "/services/control/resources/"
                                + action + "/act")).header("Content-Type", "application/json")
                        .POST(java.net.http.HttpRequest.BodyPublishers.ofString(body)).build(),
                java.net.http.HttpResponse.BodyHandlers.ofString());
        assertThat(answer.statusCode()).as(device + " " + action + ": " + answer.body()).isEqualTo(200);
    }

    private static String find(String text, String regex) {
        Matcher m = Pattern.compile(regex).matcher(text);
        assertThat(m.find()).as(regex + " in\n" + text).isTrue();
        return m.group(1);
    }

    private static boolean listening(int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress("127.0.0.1", port), 500);
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
