package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Launches the exported node as the README does and uses it through its Gogo shell: the ready line, the bus's
 * commands, the framework's and SCR's commands, the edge's commands and its REST API on loopback, a configuration
 * file and a bundle picked up from the config folder, and the check mode's exit code.
 */
class FabricNodeSmokeTest {

    private static final String READY = "fabric node ready in ";
    private static final String ALL_ACTIVE = "fabric node: start levels 1 and 2 up in ";

    @TempDir
    Path configDir;

    @Test
    void startsWithTheBusAndAnInteractiveShell() throws Exception {
        Files.writeString(configDir.resolve("eu.brain.iot.eventing.cfg"), "queue.capacity=1234\n");
        TestBundles.write(configDir.resolve("extra.jar"), "test.extra", "Bundle-Name",
                "Extra bundle dropped in the config folder");
        int httpPort = NodeProcess.freePort();
        try (NodeProcess node = NodeProcess.start("-Dfelix.fileinstall.dir=" + configDir,
                "-Dorg.osgi.service.http.port=" + httpPort)) {
            String started = node.awaitOutput(READY);
            assertThat(started).doesNotContain("WITH PROBLEMS").doesNotContain("Exception");
            // then the edge and Felix HTTP start; the Gogo shell comes after both lines, so its prompt is last
            String prompted = node.awaitOutput("g! ");
            assertThat(prompted).containsPattern(ALL_ACTIVE + "\\d+ ms \\(the core, then the edge and its REST API\\): "
                    + "\\d+ of \\d+ bundles active; dashboard: http://127\\.0\\.0\\.1:\\d+/dashboard/; "
                    + "the other (one starts|\\d+ start) at level 3: the Gogo shell"
                    + "( and the config folder's bundles)?, last so that its prompt follows this line");
            assertThat(prompted.indexOf("g! ")).isGreaterThan(prompted.indexOf(ALL_ACTIVE))
                    .isGreaterThan(prompted.indexOf(READY));

            node.type("bus:behaviours");
            node.awaitOutput("QUEUED");
            node.type("bus:stats");
            node.awaitOutput("PUBLISHED");

            node.type("lb");
            assertThat(node.awaitOutput("BRAIN-IoT fabric: event bus")).containsPattern(
                    "\\|Active +\\| +\\d+\\|BRAIN-IoT fabric: event bus");

            node.type("scr:list");
            assertThat(node.awaitOutput("EventBusComponent")).containsPattern(
                    "EventBusComponent in bundle \\d+ \\([^)]*\\) enabled, 1 instance\\.\\s+Id: \\d+, State:ACTIVE");

            // the edge: its bundle, its Gogo commands, and its REST API on 127.0.0.1 (no fleet is running here:
            // the edge keeps trying, and its model is empty meanwhile)
            node.type("lb");
            assertThat(node.awaitOutput("BRAIN-IoT fabric: edge")).containsPattern(
                    "\\|Active +\\| +\\d+\\|BRAIN-IoT fabric: edge");
            node.type("edge:robots");
            node.awaitOutput("HEADING");
            node.type("edge:stats");
            node.awaitOutput("polls sent");
            HttpResponse<String> providers = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                    URI.create("http://127.0.0.1:" + httpPort + "/sensinact/providers")).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertThat(providers.statusCode()).isEqualTo(200);
            assertThat(providers.body()).startsWith("[");

            // node/config's role: Config Admin gets the file's values through File Install
            await("the bus configured from " + configDir).atMost(NodeProcess.DEADLINE)
                    .pollInterval(Duration.ofMillis(300)).until(() -> {
                        node.type("scr:info eu.brain.iot.eventing.impl.EventBusComponent");
                        return node.output().contains("queue.capacity<String> = 1234");
                    });

            // a bundle dropped in the config folder is installed and started after the launch
            await("the dropped bundle active").atMost(NodeProcess.DEADLINE).pollInterval(Duration.ofMillis(300))
                    .until(() -> {
                        node.type("lb");
                        return node.output().matches("(?s).*\\|Active +\\| +\\d+\\|Extra bundle dropped.*");
                    });

            node.type("stop 0");
            node.awaitExit();
            assertThat(node.output()).doesNotContain("Exception");
        }
    }

    @Test
    void aCheckRunWaitingForAServiceThatNeverComesGivesUpAtItsDeadline() throws Exception {
        try (NodeProcess node = NodeProcess.start("-Dfabric.node.exitWhenReady=true",
                "-Dfabric.node.ready.services=no.such.Service", "-Dfabric.node.check.timeout=3",
                "-Dfelix.fileinstall.dir=" + configDir, "-Dorg.osgi.service.http.port=" + NodeProcess.freePort())) {
            assertThat(node.awaitExit()).as("exit code; output:%n%s", node.output()).isEqualTo(1);
            assertThat(node.output()).contains("fabric node: check run gave up after 3 s "
                    + "(fabric.node.check.timeout=3), "
                    + "still waiting for: service no.such.Service (fabric.node.ready.services)")
                    .doesNotContain(READY);
        }
    }


    @Test
    void withoutAShellTheReadyLineSaysHowToStopTheNode() throws Exception {
        try (NodeProcess node = NodeProcess.start("-Dgosh.args=--nointeractive",
                "-Dfelix.fileinstall.dir=" + configDir, "-Dorg.osgi.service.http.port=" + NodeProcess.freePort())) {
            String started = node.awaitOutput(ALL_ACTIVE);
            assertThat(started).contains("no shell (gosh.args=--nointeractive): stop it with Ctrl-C or kill "
                    + node.pid()).doesNotContain("'stop 0'").doesNotContain("WITH PROBLEMS");
            node.terminate();
            assertThat(node.awaitExit()).as("exit code after SIGTERM; output:%n%s", node.output()).isEqualTo(143);
            assertThat(node.output()).doesNotContain("Welcome to Apache Felix Gogo").doesNotContain("Exception");
        }
    }

    @Test
    void checkModePrintsTheStartupTimeAndExitsWithZero() throws Exception {
        try (NodeProcess node = NodeProcess.start("-Dfabric.node.exitWhenReady=true",
                "-Dfelix.fileinstall.dir=" + configDir, "-Dorg.osgi.service.http.port=" + NodeProcess.freePort())) {
            assertThat(node.awaitExit()).as("exit code; output:%n%s", node.output()).isZero();
            assertThat(node.output())
                    .containsPattern(READY + "\\d+ ms \\(JVM start to event bus up; start level 1: \\d+ of \\d+ "
                            + "bundles active, the other \\d+ start next\\); check run")
                    .containsPattern(ALL_ACTIVE + "\\d+ ms [^\\n]*: (\\d+) of (\\d+) bundles active; dashboard: "
                            + "http://127\\.0\\.0\\.1:\\d+/dashboard/; a check run "
                            + "stops here, before level 3 \\(the Gogo shell\\)")
                    .as("no shell in check mode").doesNotContain("Welcome to Apache Felix Gogo")
                    .doesNotContain("Exception")
                    .as("SPI Fly's INFO lines are silenced (fabric.node.jul.levels)")
                    .doesNotContain("Registered provider");
        }
    }
}
