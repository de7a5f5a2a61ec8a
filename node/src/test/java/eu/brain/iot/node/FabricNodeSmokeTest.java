package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Launches the exported node as the README does and uses it through its Gogo shell: the ready line, the bus's
 * commands, the framework's and SCR's commands, a configuration file and a bundle picked up from the config
 * folder, and the check mode's exit code.
 */
class FabricNodeSmokeTest {

    private static final String READY = "fabric node ready in ";

    @TempDir
    Path configDir;

    @Test
    void startsWithTheBusAndAnInteractiveShell() throws Exception {
        Files.writeString(configDir.resolve("eu.brain.iot.eventing.cfg"), "queue.capacity=1234\n");
        TestBundles.write(configDir.resolve("extra.jar"), "test.extra", "Bundle-Name",
                "Extra bundle dropped in the config folder");
        try (NodeProcess node = NodeProcess.start("-Dfelix.fileinstall.dir=" + configDir)) {
            String started = node.awaitOutput(READY);
            assertThat(started).doesNotContain("WITH PROBLEMS").doesNotContain("Exception");
            // the Gogo shell starts after the ready line, so that its prompt is the last thing on the console
            String prompted = node.awaitOutput("g! ");
            assertThat(prompted.indexOf("g! ")).isGreaterThan(prompted.indexOf(READY));

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
    void checkModePrintsTheStartupTimeAndExitsWithZero() throws Exception {
        try (NodeProcess node = NodeProcess.start("-Dfabric.node.exitWhenReady=true",
                "-Dfelix.fileinstall.dir=" + configDir)) {
            assertThat(node.awaitExit()).as("exit code; output:%n%s", node.output()).isZero();
            assertThat(node.output()).containsPattern(READY + "\\d+ ms \\(JVM start to event bus up, \\d+ bundles\\)")
                    .as("no shell in check mode").doesNotContain("Gogo").doesNotContain("Exception");
        }
    }
}
