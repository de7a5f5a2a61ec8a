package eu.brain.iot.broker;

import static org.awaitility.Awaitility.await;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

/**
 * {@code java -jar target/broker.jar ...} as a user runs it, its output (standard output and error merged) kept
 * line by line. Threads: the test thread starts and stops it; one reader thread appends to {@link #lines()}.
 */
final class BrokerProcess implements AutoCloseable {
    private final Process process;
    private final List<String> lines = new CopyOnWriteArrayList<>();

    private BrokerProcess(Process process) {
        this.process = process;
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(
                    new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = r.readLine(); line != null; line = r.readLine()) {
                    lines.add(line);
                }
            } catch (IOException e) {
                lines.add("(reading the broker's output failed: " + e + ")");
            }
        }, "broker-output");
        reader.setDaemon(true);
        reader.start();
    }

    static BrokerProcess start(String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-jar",
                Path.of("target", "broker.jar").toAbsolutePath().toString()));
        command.addAll(List.of(args));
        return new BrokerProcess(new ProcessBuilder(command).redirectErrorStream(true).start());
    }

    /** Starts one and waits for its ready line. */
    static BrokerProcess started(String... args) throws IOException {
        BrokerProcess broker = start(args);
        broker.awaitLine(BrokerMain.READY_PREFIX);
        return broker;
    }

    String awaitLine(String prefix) {
        await("a line starting with '" + prefix + "' from the broker").atMost(Duration.ofSeconds(90))
                .pollInterval(Duration.ofMillis(50))
                .until(() -> lines.stream().anyMatch(l -> l.startsWith(prefix)) || !process.isAlive());
        return lines.stream().filter(l -> l.startsWith(prefix)).findFirst()
                .orElseThrow(() -> new AssertionError("the broker ended (exit code " + process.exitValue()
                        + ") without '" + prefix + "'; its output: " + lines));
    }

    int awaitExit() throws InterruptedException {
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            throw new AssertionError("the broker did not end within 60 s; its output: " + lines);
        }
        return process.exitValue();
    }

    List<String> lines() {
        return lines;
    }

    long pid() {
        return process.pid();
    }

    /** SIGTERM, and waits for the JVM to end (its shutdown hook stops the broker). */
    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
        }
    }

    static int freePort() {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
