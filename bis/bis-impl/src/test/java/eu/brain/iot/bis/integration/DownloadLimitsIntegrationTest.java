package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.DOOR;
import static eu.brain.iot.bis.integration.TestRepository.DOOR_CLOSED;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT;
import static eu.brain.iot.bis.integration.TestRepository.ROBOT_UNLOAD;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.osgi.util.promise.Promise;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.integration.TestHttpServer.Behaviour;

/**
 * Repositories and downloads that misbehave, served by a real HTTP server on loopback: an index that never ends, one
 * that trickles, one that never answers, a bundle that trickles or never ends. Each is abandoned within its bound,
 * with an error naming its URL, and holds up nothing else: the other indexes answer, other behaviours install, the
 * shell's command returns.
 */
class DownloadLimitsIntegrationTest extends BisTestBase {

    /** Well below the time the misbehaving reads would take: what answers must not wait for them. */
    private static final Duration PROMPTLY = Duration.ofSeconds(5);

    @Test
    void indexesThatNeverEndTrickleOrNeverAnswerHideNoOtherIndex() throws Exception {
        try (TestHttpServer server = new TestHttpServer(repo.dir)) {
            server.misbehave("/endless.xml", Behaviour.ENDLESS).misbehave("/silent.xml", Behaviour.SILENT)
                    .misbehave("/index.xml", Behaviour.TRICKLE);
            var settings = settings();
            settings.put("repositories", new String[] { server.url("/endless.xml"), server.url("/silent.xml"),
                    server.url("/index.xml"), repo.index.toUri().toString() });
            settings.put("index.max.bytes", 1_000_000L);
            settings.put("download.deadline.ms", 3_000L);
            BundleInstaller installer = configure(settings);

            // the local index, listed last, is in use at once
            await().atMost(PROMPTLY).until(() -> !installer.find(List.of(DOOR_CLOSED)).getValue().isEmpty());
            InstalledBehaviour door = value(installer.install(byType(DOOR_CLOSED)));
            assertThat(door.repository).isEqualTo(repo.index.toUri().toString());

            // each repository is read on its own thread: the three problems come in any order, each within its bound
            List<String> problems = List.of(server.url("/endless.xml") + " is longer than the 1000000 bytes allowed",
                    server.url("/silent.xml") + " did not answer within 3000 ms",
                    server.url("/index.xml") + " did not send its whole body within 3000 ms");
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(command("repos")).contains(problems));
            assertThat(command("repos")).doesNotContain("(null)");
        }
    }

    @Test
    void anIndexThatNeverAnswersDoesNotHoldBackTheJournalsRestore() throws Exception {
        BundleInstaller installer = configure(settings());
        awaitOffered(installer, DOOR_CLOSED);
        value(installer.install(byType(DOOR_CLOSED)));
        unconfigure();
        for (String name : List.of(DOOR, TestRepository.EVENTS, TestRepository.WAREHOUSE, TestRepository.EDGE_API,
                TestRepository.EDGE_MODEL_API)) {
            bundle(name).uninstall(); // as a node restart's cache wipe would
        }
        try (TestHttpServer server = new TestHttpServer(repo.dir)) {
            server.misbehave("/silent.xml", Behaviour.SILENT);
            var settings = settings();
            settings.put("repositories", new String[] { server.url("/silent.xml"), repo.index.toUri().toString() });
            settings.put("download.timeout.ms", 20_000L);
            settings.put("restore.timeout.ms", 30_000L);

            long started = System.nanoTime();
            BundleInstaller restarted = configure(settings);

            assertThat(Duration.ofNanos(System.nanoTime() - started)).isLessThan(Duration.ofSeconds(10));
            assertThat(restarted.installed()).extracting(b -> b.symbolicName).containsExactly(DOOR);
            assertThat(bundle(DOOR)).isNotNull();
        }
    }

    @Test
    void aTricklingBundleHoldsUpOnlyItsOwnInstallAndTheShellSaysWhatItWaitsFor() throws Exception {
        try (TestHttpServer server = new TestHttpServer(repo.dir)) {
            String doorJar = "/" + repo.jar("behaviour-door").getFileName();
            server.misbehave(doorJar, Behaviour.TRICKLE);
            var settings = settings();
            settings.put("repositories", new String[] { server.url("/index.xml") });
            settings.put("download.deadline.ms", 8_000L);
            settings.put("shell.wait.ms", 1_000L);
            BundleInstaller installer = configure(settings);
            awaitOffered(installer, DOOR_CLOSED);

            Promise<InstalledBehaviour> door = installer.install(byType(DOOR_CLOSED));
            await().atMost(PROMPTLY).until(() -> String.join("\n", installer.activities())
                    .contains("downloading " + DOOR));

            // another behaviour installs meanwhile, without waiting for the door's download
            long started = System.nanoTime();
            InstalledBehaviour robot = value(installer.install(byType(ROBOT_UNLOAD)).timeout(PROMPTLY.toMillis()));
            assertThat(robot.symbolicName).isEqualTo(ROBOT);
            assertThat(Duration.ofNanos(System.nanoTime() - started)).isLessThan(PROMPTLY);
            assertThat(door.isDone()).isFalse();

            // the shell's command returns, saying what the installer is doing
            started = System.nanoTime();
            String answer = command("install", DOOR);
            assertThat(Duration.ofNanos(System.nanoTime() - started)).isLessThan(Duration.ofSeconds(3));
            assertThat(answer).contains("no answer yet after 1 s").contains("downloading " + DOOR)
                    .contains(server.url(doorJar));

            InstallException failure = failure(door);
            assertThat(failure.problem()).isEqualTo(Problem.DOWNLOAD_FAILED);
            assertThat(failure.getMessage()).contains(server.url(doorJar)).contains("within 8000 ms");
            assertThat(bundle(DOOR)).isNull();
        }
    }

    @Test
    void aBundleThatNeverEndsIsCutAtTheSizeItsIndexStates() throws Exception {
        try (TestHttpServer server = new TestHttpServer(repo.dir)) {
            String doorJar = "/" + repo.jar("behaviour-door").getFileName();
            long size = Files.size(repo.jar("behaviour-door"));
            server.misbehave(doorJar, Behaviour.ENDLESS);
            var settings = settings();
            settings.put("repositories", new String[] { server.url("/index.xml") });
            BundleInstaller installer = configure(settings);
            awaitOffered(installer, DOOR_CLOSED);

            long started = System.nanoTime();
            InstallException failure = failure(installer.install(byType(DOOR_CLOSED)));

            assertThat(Duration.ofNanos(System.nanoTime() - started)).isLessThan(PROMPTLY);
            assertThat(failure.problem()).as("it does not match its index").isEqualTo(Problem.HASH_MISMATCH);
            assertThat(failure.getMessage()).contains(server.url(doorJar) + " is longer than the " + size
                    + " bytes allowed");
            assertThat(bundle(DOOR)).isNull();
        }
    }
}
