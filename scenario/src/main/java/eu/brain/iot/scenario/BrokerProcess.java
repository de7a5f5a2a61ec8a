package eu.brain.iot.scenario;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The embedded MQTT 5 broker (broker/README.md) in a process of its own, as node/bin/fabric-nodes.sh starts it:
 * {@code java -jar broker/target/broker.jar --port P --data <run>/broker --in-memory} on a free port of 127.0.0.1,
 * its output in {@code <run>/broker.log}; ready when it prints {@code broker listening on }.
 * <p>
 * Threads: started and awaited on the runner's thread; {@link #stop} may also run on the shutdown hook and is
 * idempotent.
 */
final class BrokerProcess {
    /** The broker's line once clients can connect. */
    static final String READY = "broker listening on ";
    private static final Duration READY_TIMEOUT = Duration.ofSeconds(60);
    private static final Duration STOP_GRACE = Duration.ofSeconds(15);
    private static final long LOOK_EVERY_MS = 100;

    private final Process process;
    private final Path log;
    private final int port;

    private BrokerProcess(Process process, Path log, int port) {
        this.process = process;
        this.log = log;
        this.port = port;
    }

    /**
     * Starts the broker and waits until it accepts connections.
     *
     * @param root   the repository root (broker/target/broker.jar)
     * @param folder where its state folder ({@code broker}) and log ({@code broker.log}) go
     * @throws IOException when the jar is missing, or the broker ended or was not ready in time (its log's end said)
     */
    static BrokerProcess start(Path root, Path folder) throws IOException, InterruptedException {
        Path jar = root.resolve("broker/target/broker.jar");
        if (!Files.isRegularFile(jar)) {
            throw new IOException(jar + " is missing: build it (./warehouse-scenario does for --nodes 2 or more; or "
                    + "mvn -B -q -pl broker package -DskipTests)");
        }
        int port = NodeSetup.freePort();
        Path log = folder.resolve("broker.log");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-jar", jar.toString(), "--port", String.valueOf(port), "--data",
                folder.resolve("broker").toString(), "--in-memory"));
        Process p = new ProcessBuilder(command).directory(root.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile()).redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")))
                .start();
        BrokerProcess broker = new BrokerProcess(p, log, port);
        try {
            broker.awaitReady();
        } catch (IOException | InterruptedException e) {
            broker.stop();
            throw e;
        }
        return broker;
    }

    private void awaitReady() throws IOException, InterruptedException {
        long until = System.nanoTime() + READY_TIMEOUT.toNanos();
        while (!ready()) {
            if (!process.isAlive() || System.nanoTime() > until) {
                String why = process.isAlive() ? "was not ready within " + READY_TIMEOUT.toSeconds() + " s"
                        : "ended (exit code " + process.exitValue() + ")";
                throw new IOException("the embedded broker " + why + "; the end of its log " + log + ": "
                        + String.join(" | ", tail()));
            }
            Thread.sleep(LOOK_EVERY_MS);
        }
    }

    private boolean ready() throws IOException {
        return Files.isRegularFile(log)
                && Files.readAllLines(log, StandardCharsets.UTF_8).stream().anyMatch(l -> l.startsWith(READY));
    }

    private List<String> tail() throws IOException {
        List<String> lines = Files.isRegularFile(log) ? Files.readAllLines(log, StandardCharsets.UTF_8) : List.of();
        return lines.subList(Math.max(0, lines.size() - 10), lines.size());
    }

    /** The URI the nodes join. */
    String uri() {
        return "tcp://127.0.0.1:" + port;
    }

    long pid() {
        return process.pid();
    }

    Path log() {
        return log;
    }

    /** SIGTERM (HiveMQ stops cleanly), then SIGKILL after 15 s. Idempotent. */
    void stop() {
        if (!process.isAlive()) {
            return;
        }
        process.destroy();
        try {
            if (!process.waitFor(STOP_GRACE.toMillis(), TimeUnit.MILLISECONDS)) {
                process.destroyForcibly();
                process.waitFor(5, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }
}
