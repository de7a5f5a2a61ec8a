package eu.brain.iot.containers;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.testcontainers.DockerClientFactory;

/**
 * Whether a Docker engine answers, asked once per test JVM with a deadline, so that a machine without one skips
 * the container tests (saying why) instead of failing or hanging.
 *
 * <p>Threads: {@link #unavailableReason()} is synchronized; the engine is asked on a pool thread and waited for.
 */
final class DockerEngine {
    /** Docker's own socket, where Testcontainers looks first when DOCKER_HOST is not set. */
    static final Path DEFAULT_SOCKET = Path.of("/var/run/docker.sock");
    private static final Duration ANSWER_TIMEOUT = Duration.ofSeconds(30);
    private static final String HOW = " .ci/run installs and starts one (apt-get install docker.io; dockerd).";

    private static boolean asked;
    private static String reason;

    private DockerEngine() {
    }

    /** Skips the calling test class (a JUnit assumption) when no engine answers, with the reason. */
    static void assumeAvailable() {
        String why = unavailableReason();
        Assumptions.assumeTrue(why == null, () -> "container tests skipped: " + why);
    }

    /** Null when an engine answers, else why not. */
    static synchronized String unavailableReason() {
        if (!asked) {
            asked = true;
            reason = ask();
            if (reason != null) {
                System.out.println("container tests skipped: " + reason);
            }
        }
        return reason;
    }

    private static String ask() {
        String dockerHost = System.getenv("DOCKER_HOST");
        if ((dockerHost == null || dockerHost.isBlank()) && !Files.exists(DEFAULT_SOCKET)) {
            return "no Docker engine on this machine (" + DEFAULT_SOCKET + " does not exist, DOCKER_HOST is not set)."
                    + HOW;
        }
        CompletableFuture<Boolean> answer = CompletableFuture.supplyAsync(
                () -> DockerClientFactory.instance().isDockerAvailable());
        try {
            if (answer.get(ANSWER_TIMEOUT.toSeconds(), TimeUnit.SECONDS)) {
                return null;
            }
            return "the Docker engine at " + where(dockerHost) + " does not answer." + HOW;
        } catch (java.util.concurrent.TimeoutException e) {
            answer.cancel(true);
            return "the Docker engine at " + where(dockerHost) + " did not answer within " + ANSWER_TIMEOUT.toSeconds()
                    + " s." + HOW;
        } catch (java.util.concurrent.ExecutionException e) {
            return "asking the Docker engine at " + where(dockerHost) + " failed: " + e.getCause() + "." + HOW;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted while asking the Docker engine";
        }
    }

    private static String where(String dockerHost) {
        return dockerHost == null || dockerHost.isBlank() ? "unix://" + DEFAULT_SOCKET : dockerHost;
    }
}
