package eu.brain.iot.bis.integration;

import static eu.brain.iot.bis.integration.TestRepository.DOOR;
import static eu.brain.iot.bis.integration.TestRepository.DOOR_CLOSED;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.ServerSocket;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * The repository served over real HTTP by another process, a plain static file server (Python's http.server, which
 * answers If-Modified-Since with 304), that starts only after the installer has tried and failed to reach it.
 */
class HttpRepositoryIntegrationTest extends BisTestBase {

    @Test
    void anUnreachableRepositoryIsRetriedUntilItAnswersThenServesAnInstall() throws Exception {
        Assumptions.assumeTrue(python(), "python3 is not on the PATH: this test needs a plain HTTP server process");
        int port;
        try (ServerSocket probe = new ServerSocket(0)) {
            port = probe.getLocalPort();
        }
        repo.sign(keys, repo.dir.resolve("index.xml.gz")); // the gzipped index, with its own signature
        var settings = settings();
        settings.put("repositories", new String[] { "http://127.0.0.1:" + port + "/index.xml.gz" });
        BundleInstaller installer = configure(settings);

        // nobody listens yet: the installer retries with backoff and says so
        await().atMost(DEADLINE).until(() -> command("repos").contains("retry 3"));
        assertThat(command("repos")).contains("cannot be read").doesNotContain("(null)");
        assertThat(value(installer.find(List.of(DOOR_CLOSED)))).isEmpty();

        Process server = new ProcessBuilder("python3", "-m", "http.server", Integer.toString(port), "--bind",
                "127.0.0.1", "--directory", repo.dir.toString()).redirectErrorStream(true)
                .redirectOutput(temp.resolve("http.log").toFile()).start();
        try {
            awaitOffered(installer, DOOR_CLOSED);
            assertThat(command("repos")).contains("signature: valid");

            InstalledBehaviour door = value(installer.install(byType(DOOR_CLOSED)));

            assertThat(door.symbolicName).isEqualTo(DOOR);
            assertThat(door.repository).isEqualTo("http://127.0.0.1:" + port + "/index.xml.gz");
            assertThat(busKnows(DOOR)).isTrue();
            // later reads are conditional: the server answers 304 Not Modified
            await().atMost(DEADLINE).until(() -> java.nio.file.Files.readString(temp.resolve("http.log"))
                    .contains("\"GET /index.xml.gz HTTP/1.1\" 304"));
        } finally {
            server.destroy();
            server.waitFor(10, TimeUnit.SECONDS);
        }
    }

    private static boolean python() {
        try {
            return new ProcessBuilder("python3", "--version").start().waitFor(10, TimeUnit.SECONDS);
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }
}
