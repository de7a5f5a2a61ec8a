package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The exported node with the project's behaviour repository (the signed index repository/ built, trusting the key
 * the build generated), as {@code node/config/eu.brain.iot.bis.cfg} configures it, but with a journal of its own:
 * it starts without any behaviour; an event published from its shell installs the door behaviour, which receives
 * it; after a restart the journal's behaviour is back before the ready line.
 */
class BehavioursOnDemandNodeTest {

    private static final String READY = "fabric node ready in ";
    private static final String DOOR_EVENT = "eu.brain.iot.behaviours.events.ConnectorTypeDoor";
    private static final Path REPOSITORY = Path.of("..", "repository", "target").toAbsolutePath().normalize();
    private static final Pattern INSTALLED_COUNT = Pattern.compile(
            READY + "\\d+ ms \\([^;]*; start level 1: \\d+ of (\\d+) bundles active");

    @TempDir
    Path configDir;
    @TempDir
    Path journal;

    @Test
    void anEventFromTheShellInstallsItsBehaviourAndTheJournalBringsItBackBeforeTheReadyLine() throws Exception {
        Files.writeString(configDir.resolve("eu.brain.iot.bis.cfg"),
                "repositories=" + REPOSITORY.resolve("repository/index.xml") + "\n"
                        + "trusted.keys=" + REPOSITORY.resolve("index-signing.pub") + "\n"
                        + "journal.dir=" + journal + "\n");
        int before;
        try (NodeProcess node = start()) {
            String ready = node.awaitOutput(READY);
            before = installedCount(ready);
            node.awaitOutput("g! ");
            node.type("bus:behaviours");
            assertThat(node.awaitOutput("QUEUED")).doesNotContain("eu.brain.iot.behaviours.door");

            node.type("bus:publish " + DOOR_EVENT + " connector=c1 initiator=robot1");
            await("the door behaviour installed and given the event").atMost(NodeProcess.DEADLINE)
                    .pollInterval(Duration.ofMillis(500)).until(() -> {
                        node.type("bus:behaviours");
                        return Pattern.compile("Door_behavior#\\d+ +eu\\.brain\\.iot\\.behaviours\\.door +0 +1 ")
                                .matcher(node.output()).find();
                    });
            node.type("bis:list");
            assertThat(node.awaitOutput("why: an event of type " + DOOR_EVENT))
                    .containsPattern("eu\\.brain\\.iot\\.behaviours\\.door \\S+ +ACTIVE");
            node.type("bms:history");
            assertThat(node.awaitOutput("INSTALLED ")).containsPattern("INSTALLED +" + Pattern.quote(DOOR_EVENT));
            node.type("stop 0");
            node.awaitExit();
            assertThat(node.output()).doesNotContain("Exception");
        }

        try (NodeProcess node = start()) {
            String ready = node.awaitOutput(READY);
            // the door bundle and the two it needs (the event types, the warehouse helpers) were installed and
            // started before the ready line
            assertThat(installedCount(ready)).isEqualTo(before + 3);
            node.awaitOutput("g! ");
            node.type("bus:behaviours");
            assertThat(node.awaitOutput("QUEUED")).contains("eu.brain.iot.behaviours.door");
            node.type("bis:list");
            assertThat(node.awaitOutput("why: journal")).containsPattern(
                    "eu\\.brain\\.iot\\.behaviours\\.door \\S+ +ACTIVE");
            node.type("stop 0");
            node.awaitExit();
        }
    }

    private NodeProcess start() throws Exception {
        return NodeProcess.start("-Dfelix.fileinstall.dir=" + configDir,
                "-Dorg.osgi.service.http.port=" + NodeProcess.freePort(),
                "-Dfabric.node.jul.levels=org.apache.aries.spifly=WARNING");
    }

    private static int installedCount(String output) {
        Matcher m = INSTALLED_COUNT.matcher(output);
        assertThat(m.find()).as("the ready line in:%n%s", output).isTrue();
        return Integer.parseInt(m.group(1));
    }

}
