package eu.brain.iot.containers;

import com.github.dockerjava.api.command.InspectContainerResponse;
import java.time.Duration;
import java.util.regex.Pattern;
import org.testcontainers.DockerClientFactory;
import org.testcontainers.containers.ContainerLaunchException;
import org.testcontainers.containers.wait.strategy.AbstractWaitStrategy;

/**
 * Waits until the container's output has a line matching the pattern, and gives up at once, with the output's
 * end, when the container ends first (Testcontainers' own log wait lets the whole start-up time-out pass).
 *
 * <p>Threads: Testcontainers calls {@link #waitUntilReady()} on the thread that starts the container.
 */
final class LogLineWait extends AbstractWaitStrategy {
    private static final Duration POLL = Duration.ofMillis(100);
    private static final int TAIL_LINES = 40;

    private final Pattern line;

    LogLineWait(String lineRegex) {
        this.line = Pattern.compile(lineRegex, Pattern.MULTILINE);
    }

    @Override
    protected void waitUntilReady() {
        long deadline = System.nanoTime() + startupTimeout.toNanos();
        String id = waitStrategyTarget.getContainerId();
        while (true) {
            String logs = waitStrategyTarget.getLogs();
            if (line.matcher(logs).find()) {
                return;
            }
            InspectContainerResponse.ContainerState state = DockerClientFactory.instance().client()
                    .inspectContainerCmd(id).exec().getState();
            if (!Boolean.TRUE.equals(state.getRunning())) {
                throw new ContainerLaunchException("the container ended (exit code " + state.getExitCodeLong()
                        + ") before printing a line matching '" + line + "'; its output's end:\n" + tail(logs));
            }
            if (System.nanoTime() > deadline) {
                throw new ContainerLaunchException("no line matching '" + line + "' within "
                        + startupTimeout.toSeconds() + " s; the output's end:\n" + tail(logs));
            }
            try {
                Thread.sleep(POLL.toMillis()); // polls the container's state: no event to wait on
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new ContainerLaunchException("interrupted while waiting for " + line);
            }
        }
    }

    private static String tail(String logs) {
        return tail(logs, TAIL_LINES);
    }

    /** The last {@code count} lines of a container's output (for the tests' failure messages too). */
    static String tail(String logs, int count) {
        String[] lines = logs.split("\n");
        return String.join("\n", java.util.Arrays.copyOfRange(lines, Math.max(0, lines.length - count),
                lines.length));
    }
}
