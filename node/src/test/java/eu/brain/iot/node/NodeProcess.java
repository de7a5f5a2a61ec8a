package eu.brain.iot.node;

import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The exported fabric node (target/fabric-node.jar) run as a user runs it: its own JVM, the Gogo shell on
 * stdin/stdout. Output (stdout and stderr merged) is collected by a reader thread; {@link #output} is guarded by
 * itself.
 */
final class NodeProcess implements AutoCloseable {

    static final Path JAR = Path.of("target", "fabric-node.jar");
    static final Duration DEADLINE = Duration.ofSeconds(20);

    private final Process process;
    private final Writer stdin;
    private final StringBuilder output = new StringBuilder();

    private NodeProcess(Process process) {
        this.process = process;
        this.stdin = process.outputWriter(StandardCharsets.UTF_8);
        Thread reader = new Thread(this::collectOutput, "fabric-node-output");
        reader.setDaemon(true);
        reader.start();
    }

    /**
     * Starts {@code java <systemProperties> -jar target/fabric-node.jar}; each argument is a {@code -Dname=value}.
     * Unless one names it, the node gets a fresh state folder of its own ({@code -Dfabric.node.state}): the tests'
     * nodes never share one, nor use the folder of a node the developer runs.
     */
    static NodeProcess start(String... systemProperties) throws IOException {
        if (!Files.isRegularFile(JAR)) {
            throw new IllegalStateException(JAR.toAbsolutePath() + " is missing: the smoke test runs after "
                    + "'mvn package' has exported it (run 'mvn -pl node -am verify')");
        }
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(List.of(systemProperties));
        if (command.stream().noneMatch(a -> a.startsWith("-Dfabric.node.state="))) {
            command.add("-Dfabric.node.state=" + Files.createTempDirectory("fabric-node-state"));
        }
        command.add("-jar");
        command.add(JAR.toString());
        return new NodeProcess(new ProcessBuilder(command).redirectErrorStream(true).start());
    }

    /** A loopback port free now, for a node's HTTP server: a test does not clash with a node already running. */
    static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return socket.getLocalPort();
        }
    }

    /** Types a line into the Gogo shell. */
    void type(String line) {
        try {
            stdin.write(line + "\n");
            stdin.flush();
        } catch (IOException e) {
            throw new UncheckedIOException("the node no longer reads its console; output so far:\n" + output(), e);
        }
    }

    String output() {
        synchronized (output) {
            return output.toString();
        }
    }

    /** Waits, up to the deadline, until the output contains the text; returns the output. */
    String awaitOutput(String text) {
        await("node output containing \"" + text + "\"").atMost(DEADLINE).pollInterval(Duration.ofMillis(50))
                .until(() -> output().contains(text));
        return output();
    }

    /** Waits, up to the deadline, for the JVM to end; returns its exit code. */
    int awaitExit() throws InterruptedException {
        if (!process.waitFor(DEADLINE.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new AssertionError("the node did not exit within " + DEADLINE + "; output:\n" + output());
        }
        return process.exitValue();
    }

    /** The node's JVM's process id. */
    long pid() {
        return process.pid();
    }

    /** Sends the node's JVM SIGTERM, as {@code kill <pid>} does. */
    void terminate() {
        process.destroy();
    }

    /** Kills the node's JVM with SIGKILL, as {@code kill -9 <pid>} does: no shutdown hook runs; waits for its end. */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        awaitExit();
    }

    @Override
    public void close() {
        process.destroyForcibly();
    }

    private void collectOutput() {
        char[] buffer = new char[4096];
        try (Reader in = new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8)) {
            for (int n; (n = in.read(buffer)) >= 0;) {
                synchronized (output) {
                    output.append(buffer, 0, n);
                }
            }
        } catch (IOException e) {
            // the process ended: nothing more to collect
        }
    }
}
