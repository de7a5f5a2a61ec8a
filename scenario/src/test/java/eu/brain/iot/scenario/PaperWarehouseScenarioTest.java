package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInfo;

/**
 * The whole chain as a user runs it: the runner starts robot-sim with the paper's warehouse and a bare
 * node (its core and the edge); the BMS installs the robot, door and orchestrator behaviours on demand from the
 * repository the build made; they drive the fleet through the edge until every cart is in storage and every robot
 * docked. The verdict is the runner's, on robot-sim's ground truth (REQ-1, REQ-2). With faults: a
 * robot offline mid-errand, and a behaviour bundle stopped mid-scenario.
 *
 * <p>Speed 5 (not the command's 10): REQ-2's 10 s limit is then 2 s of wall time, which leaves room on a loaded CI
 * machine for the behaviours' reactions (a poll every 50 ms of wall time). Each run took 7-12 s of wall time after
 * the node's 2-5 s start, on 2 cores at load 1-7 (about 35 s for the class). The seed differs from the command's
 * default (1), which acceptance runs.
 *
 * <p>Each run's folder (node configuration, node.log, report.json) is kept under
 * {@code scenario/target/chain-runs/<test>-<time>}, so that a failed run in CI can be read afterwards.
 */
class PaperWarehouseScenarioTest {
    private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();
    private static final String[] BEHAVIOURS = {"robot", "door", "orchestrator"};

    @Test
    void aBareNodeInstallsTheBehavioursOnDemandAndThePapersWarehouseCompletes(TestInfo test) throws Exception {
        Path run = runDir(test);
        String text = runScenario(run);

        assertThat(text).contains("PASS  REQ-1 every cart lifted and carried to storage: 3/3 carts in storage",
                "PASS  REQ-2 no wait behind another robot longer than 10.0 s",
                "PASS  REQ-2 no robots blocking each other in a cycle for 10.0 s: 0 deadlocks",
                "PASS  REQ-2 every errand's destination reached, every robot back in docking: 3/3 robots docked",
                "PASS  every command accepted or its refusal handled", "PASS  finished before the deadline");
        JsonNode figures = report(run).path("figures");
        assertThat(figures.path("deadlocks").asInt()).isZero();
        assertThat(figures.path("waitMaxMs").asLong()).isLessThanOrEqualTo(10_000);
        assertThat(figures.path("warehouseSecondsUntilAllDelivered").asDouble()).isPositive();
        assertThat(figures.path("commandsRefused").asInt()).isZero();
        // every command the behaviours published reached the edge and was answered; robot-sim counted them
        assertThat(figures.path("busCommandEvents").asInt()).isPositive()
                .isEqualTo(figures.path("busCommandOutcomes").asInt());
        assertThat(figures.path("commandsAccepted").asInt()).isPositive();
        assertThat(figures.path("doorOpenings").asInt()).as("the carts stand behind the door").isPositive();
        assertInstalledOnDemand(run);
    }

    @Test
    void aRobotOfflineMidErrandIsNoticedAndFinishesItsErrandAfterItRecovers(TestInfo test) throws Exception {
        Path run = runDir(test);
        // 6 s, under REQ-2's 10 s: an offline robot stands still where it is, possibly in the only way through the
        // door, so a longer fault makes the others wait longer than the limit behind it, by the fault's own length
        // (seen with 20 s: waits of 24 and 27 s, and a deadlock counted), which is not what this test is about
        String text = runScenario(run, "--fault-offline", "robot2@12s+6s");

        assertThat(text).containsPattern("\\] fault: robot2 goes offline").contains("fault: robot2 is back online",
                "PASS  REQ-1 every cart lifted and carried to storage: 3/3 carts in storage",
                "PASS  REQ-2 every errand's destination reached, every robot back in docking: 3/3 robots docked");
        String log = Files.readString(run.resolve("node.log"));
        assertThat(log).as("the behaviours noticed").contains("robot2 is unreachable");
        assertThat(log).containsPattern("robot2 answers again after [\\d,.]+ ms: it goes on with its errand");
        // robot2 was on an errand when it went offline: it got commands after it answered again (the robot
        // behaviour's own lines, e.g. "robot2 moves to 1", "robot2 lifts a cart", or the traffic planner's first leg
        // for it: "robot2 drives on along its reserved path")
        int back = log.indexOf("robot2 answers again");
        assertThat(log.substring(back)).containsPattern("robot2 (moves to|lifts|places|drives on)");
        JsonNode report = report(run);
        assertThat(report.path("faults")).hasSize(2);
    }

    @Test
    void aBehaviourStoppedMidScenarioIsBroughtBackByTheBmsAndTheWarehouseCompletes(TestInfo test)
            throws Exception {
        Path run = runDir(test);
        // at 25 s of warehouse time the robots are out on their errands (going for their carts, carrying them to
        // storage or going home, depending on the machine's load: the errands begin once the BMS installed the robot
        // and door behaviours, 0.5-2.5 s of wall time after the start, and the last robot docks at 35-50 s), so the
        // restarted behaviour must take them over from the edge's device model: it starts with no errand of its own.
        // The BMS brings the bundle back whether or not an event of its types comes meanwhile.
        String text = runScenario(run, "--stop-behaviour", "robot@25s");

        assertThat(text).containsPattern("\\] fault: stopped eu\\.brain\\.iot\\.behaviours\\.robot .*was Active")
                .contains("PASS  stopped behaviour eu.brain.iot.behaviours.robot brought back",
                        "PASS  REQ-1 every cart lifted and carried to storage: 3/3 carts in storage",
                        "PASS  REQ-2 every errand's destination reached, every robot back in docking: 3/3 robots docked");
        String log = Files.readString(run.resolve("node.log"));
        assertThat(log).as("the BMS started the robot bundle again")
                .contains("Started again eu.brain.iot.behaviours.robot ");
        // the new instance took robots over on their errands (RobotFleet's line); the first instance never does,
        // since it meets every robot idle in its dock
        assertThat(log).containsPattern("robot\\d taken over at \\(\\d+,\\d+\\): TO_(CART|STORAGE|DOCK)");
        assertInstalledOnDemand(run);
    }

    /**
     * With --broker the node joins a fabric through a real broker (Mosquitto, started here on a free port of
     * 127.0.0.1; skipped where its binary is missing) with a key of the run's own, and the warehouse completes as on
     * a node alone; the judge says the node joined.
     */
    @Test
    void aNodeInAFabricThroughMosquittoRunsThePapersWarehouse(TestInfo test) throws Exception {
        Path mosquitto = Path.of("/usr/sbin/mosquitto");
        Assumptions.assumeTrue(Files.isExecutable(mosquitto), "Mosquitto is not installed (apt-get install "
                + "mosquitto): the run through a real broker is skipped");
        Path run = runDir(test);
        Files.createDirectories(run);
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        Path conf = run.resolve("mosquitto.conf");
        Files.writeString(conf, "listener " + port + " 127.0.0.1\nallow_anonymous true\npersistence false\n");
        Process broker = new ProcessBuilder(mosquitto.toString(), "-c", conf.toString()).redirectErrorStream(true)
                .redirectOutput(run.resolve("mosquitto.log").toFile()).start();
        try {
            int listening = port;
            org.awaitility.Awaitility.await("Mosquitto listening on " + port).atMost(java.time.Duration.ofSeconds(30))
                    .until(() -> {
                        try (java.net.Socket probe = new java.net.Socket(InetAddress.getLoopbackAddress(), listening)) {
                            return true;
                        } catch (java.io.IOException notYet) {
                            return false;
                        }
                    });
            String text = runScenario(run, "--broker", "tcp://127.0.0.1:" + port);
            assertThat(text).contains("PASS  the node joined the fabric through tcp://127.0.0.1:" + port,
                    "PASS  REQ-1 every cart lifted and carried to storage: 3/3 carts in storage",
                    "all commanded by node node1");
            assertThat(run.resolve("fabric.key")).as("a key of the run's own").isRegularFile();
        } finally {
            broker.destroy();
            broker.waitFor();
        }
    }

    /** The run's folder, kept after the test (not a temporary folder): its node.log tells why a run failed. */
    private static Path runDir(TestInfo test) {
        String time = LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss"));
        return Path.of("target", "chain-runs", test.getTestMethod().orElseThrow().getName() + "-" + time)
                .toAbsolutePath();
    }

    /** Runs the scenario to its end and asserts that it passed; returns what it printed. */
    private static String runScenario(Path run, String... extra) throws Exception {
        List<String> args = new ArrayList<>(List.of("--root", ROOT.toString(), "--seed", "3", "--speed", "5",
                "--deadline", "10", "--progress", "5", "--run-dir", run.toString()));
        args.addAll(List.of(extra));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(out, true, StandardCharsets.UTF_8);
        int code = Main.run(args.toArray(String[]::new), print, print);
        String text = out.toString(StandardCharsets.UTF_8);
        String diagnosis = text + "\n--- node.log (tail) ---\n" + tail(run.resolve("node.log"));
        assertThat(code).as(diagnosis).isZero();
        assertThat(text).as(diagnosis).contains("scenario PASSED").doesNotContain("FAIL ", "Exception");
        assertThat(report(run).path("passed").asBoolean()).isTrue();
        return text;
    }

    /**
     * The node started bare: the BMS installed each behaviour after the node was up, for an event it saw. The robot
     * and door behaviours' triggers come in every run (the first poll of each robot and door); the orchestrator's
     * comes with the first robot-in-front report, which a run without a meeting never makes (seen in CI: every cart
     * stored, no robot stopped behind another for the patience): then the orchestrator must not be installed.
     */
    private static void assertInstalledOnDemand(Path run) throws Exception {
        String log = Files.readString(run.resolve("node.log"));
        int ready = log.indexOf("fabric node ready in ");
        assertThat(ready).as("the node's ready line").isNotNegative();
        int firstReport = log.indexOf("has been stopped behind a robot for ");
        for (String b : BEHAVIOURS) {
            String line = "Installed eu.brain.iot.behaviours." + b + " ";
            if (b.equals("orchestrator") && firstReport < 0) {
                assertThat(log).as("no robot-in-front report, no orchestrator").doesNotContain(line);
                continue;
            }
            assertThat(log.indexOf(line)).as("the BMS installed " + b + " on demand, after the node was up")
                    .isGreaterThan(ready);
        }
        // more types may join an install's first: the robot binding's first inputs to the model's host, which may
        // come before the host registered; a robot's door interaction, which may come before the door is installed
        assertThat(log).containsPattern("for events of \\[eu\\.brain\\.iot\\.edge\\.api\\.RobotPositionChanged[,\\]]")
                .containsPattern("for events of \\[eu\\.brain\\.iot\\.edge\\.api\\.DoorStateChanged[,\\]]");
        if (firstReport >= 0) {
            assertThat(log.indexOf("for events of [eu.brain.iot.behaviours.events.ConnectorResolveCollisionOffer]"))
                    .as("the orchestrator installed for the first robot-in-front report").isGreaterThan(firstReport);
        }
    }

    private static JsonNode report(Path run) throws Exception {
        return ReportWriter.MAPPER.readTree(run.resolve("report.json").toFile());
    }

    /** The last 60 lines of a log, for a failed assertion's message. */
    static String tail(Path file) {
        try {
            List<String> lines = Files.readAllLines(file);
            return String.join("\n", lines.subList(Math.max(0, lines.size() - 60), lines.size()));
        } catch (Exception e) {
            return "(no " + file + ": " + e.getMessage() + ")";
        }
    }
}
