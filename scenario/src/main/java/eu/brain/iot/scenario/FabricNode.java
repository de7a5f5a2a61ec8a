package eu.brain.iot.scenario;

import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * A fabric node run as a user runs it: {@code java -jar node/target/fabric-node.jar} in its own JVM, with a
 * configuration folder of the run's own, its output (stdout and stderr) in a log file, and its Gogo shell on a pipe,
 * through which the runner types commands as an operator would ({@code lb}, {@code stop <id>}, {@code bus:stats}).
 * When the runner's JVM dies, even killed, the pipe closes: the shell reads end of input and the node stops.
 * <p>
 * Threads: the reader thread ("fabric-node-output") owns the log writer and feeds {@link #lines} and
 * {@link #ready}; one caller thread at a time uses {@link #shell} (the runner's loop); {@link #stop} may also run on
 * the JVM's shutdown hook, and is idempotent.
 */
final class FabricNode implements AutoCloseable {
    private static final String PROMPT = "g! ";
    /**
     * The node's line saying every bundle of its start levels is up: {@code fabric node: all 48 bundles active in
     * ... ms} (and, in the node's newer wording, {@code fabric node: levels 1 to 3 up in ... ms ...}).
     */
    private static final java.util.regex.Pattern UP = java.util.regex.Pattern.compile(
            "^fabric node: (all \\d+ bundles active in|.+ up in) \\d+ ms.*");

    private final Process process;
    private final Writer stdin;
    private final Path log;
    /** Lines of output (prompts stripped) for shell replies; bounded, cleared before each command. */
    private final BlockingQueue<String> lines = new ArrayBlockingQueue<>(20_000);
    /** Completes with null when every bundle is active, or with the line that says what failed. */
    private final CompletableFuture<String> ready = new CompletableFuture<>();
    private int commands;

    private FabricNode(Process process, Path log) throws IOException {
        this.process = process;
        this.log = log;
        this.stdin = process.outputWriter(StandardCharsets.UTF_8);
        BufferedWriter logWriter = Files.newBufferedWriter(log, StandardCharsets.UTF_8);
        Thread reader = new Thread(() -> pump(logWriter), "fabric-node-output");
        reader.setDaemon(true);
        reader.start();
    }

    /**
     * Starts the node.
     *
     * @param root      the repository root (the node's {@code fabric.node.root})
     * @param configDir the node's configuration folder (Felix File Install)
     * @param httpPort  the port of its REST API (127.0.0.1)
     * @param log       where its output goes
     * @param name      the node's name (framework property {@code fabric.node.name}: its edge names it on every
     *                  command, its fabric membership uses it), or null for the node's default
     */
    static FabricNode start(Path root, Path configDir, int httpPort, Path log, String name) throws IOException {
        Path jar = root.resolve("node/target/fabric-node.jar");
        if (!Files.isRegularFile(jar)) {
            throw new IOException(jar + " is missing: build it (./warehouse-scenario does; or "
                    + "mvn -B -q -pl node -am package -DskipTests)");
        }
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-Dfelix.fileinstall.dir=" + configDir);
        command.add("-Dfabric.node.root=" + root);
        // a state folder of the run's own: the node locks it, and a node the user runs from this checkout holds the
        // checkout's default one
        command.add("-Dfabric.node.state=" + configDir.toAbsolutePath().getParent().resolve("state"));
        if (name != null) {
            command.add("-Dfabric.node.name=" + name);
        }
        command.add("-Dorg.osgi.service.http.port=" + httpPort);
        command.add("-Dorg.apache.felix.http.host=127.0.0.1");
        command.add("-jar");
        command.add(jar.toString());
        Process p = new ProcessBuilder(command).directory(root.toFile()).redirectErrorStream(true).start();
        return new FabricNode(p, log);
    }

    private void pump(BufferedWriter logWriter) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(),
                StandardCharsets.UTF_8)); logWriter) {
            for (String line; (line = in.readLine()) != null;) {
                logWriter.write(line);
                logWriter.newLine();
                logWriter.flush();
                String text = line;
                while (text.startsWith(PROMPT)) {
                    text = text.substring(PROMPT.length());
                }
                if (text.contains("WITH PROBLEMS")) {
                    ready.complete(text);
                } else if (UP.matcher(text).matches()) {
                    ready.complete(null);
                } else if (text.startsWith("fabric node: check run gave up")) {
                    ready.complete(text);
                }
                lines.offer(text); // when full (nobody asked the shell for a while) older output is not needed
            }
        } catch (IOException e) {
            // the process ended or the log cannot be written: nothing more to collect
        }
        ready.complete("the node ended (exit code " + exitCode() + ") before every bundle was active");
    }

    /** The process's exit code (waiting up to 5 s for it to end), or "none yet". */
    String exitCode() {
        try {
            return process.waitFor(5, TimeUnit.SECONDS) ? String.valueOf(process.exitValue()) : "none yet";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "unknown";
        }
    }

    /**
     * Waits until every bundle of the node is active.
     *
     * @throws IOException saying why it is not (a bundle failed, the node ended, or the time ran out)
     */
    void awaitReady(Duration timeout) throws IOException, InterruptedException {
        String problem;
        try {
            problem = ready.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            problem = "the node did not say every bundle was active within " + timeout.toSeconds() + " s";
        } catch (java.util.concurrent.ExecutionException e) {
            problem = String.valueOf(e.getCause());
        }
        if (problem != null) {
            throw new IOException(problem + " (its output: " + log + ")");
        }
    }

    /**
     * Types a command into the node's Gogo shell and returns what it printed, or throws when the answer did not
     * come in time. Markers echoed before and after the command frame the answer.
     */
    List<String> shell(String command, Duration timeout) throws IOException, InterruptedException {
        int n = ++commands;
        String begin = "@@scenario-" + n + "-begin@@";
        String end = "@@scenario-" + n + "-end@@";
        lines.clear();
        type("echo " + begin);
        type(command);
        type("echo " + end);
        long until = System.nanoTime() + timeout.toNanos();
        List<String> answer = new ArrayList<>();
        boolean inside = false;
        while (true) {
            String line = lines.poll(Math.max(1, until - System.nanoTime()), TimeUnit.NANOSECONDS);
            if (line == null) {
                throw new IOException("the node's shell did not answer '" + command + "' within "
                        + timeout.toSeconds() + " s");
            }
            if (line.equals(begin)) {
                inside = true;
            } else if (line.equals(end)) {
                return answer;
            } else if (inside) {
                answer.add(line);
            }
        }
    }

    private void type(String line) throws IOException {
        stdin.write(line + "\n");
        stdin.flush();
    }

    boolean alive() {
        return process.isAlive();
    }

    long pid() {
        return process.pid();
    }

    /** CPU time the node's JVM has used so far (all its threads), or zero when the system does not say. */
    /** Every bundle is active: its shell answers at once. */
    boolean up() {
        return ready.isDone() && ready.getNow("") == null;
    }

    Duration cpu() {
        return process.toHandle().info().totalCpuDuration().orElse(Duration.ZERO);
    }

    Path log() {
        return log;
    }

    /**
     * Kills the node's JVM outright: {@link Process#destroyForcibly()}, which is SIGKILL on Linux ({@code kill -9}):
     * no shutdown hook runs, the framework does not stop, the node says no goodbye to its fabric (the broker sends
     * its Last Will). Waits up to 5 s for the process to be gone.
     */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor(5, TimeUnit.SECONDS);
    }

    /** Asks the node to stop (SIGTERM) without waiting, so that several nodes stop together; {@link #stop} waits. */
    void requestStop() {
        if (process.isAlive()) {
            process.destroy();
        }
    }

    /** Stops the node: SIGTERM (its launcher stops the framework), then, after 15 s, SIGKILL. Idempotent. */
    void stop() {
        if (process.isAlive()) {
            process.destroy();
            try {
                if (!process.waitFor(15, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                    process.waitFor(5, TimeUnit.SECONDS);
                }
            } catch (InterruptedException e) {
                process.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }

    @Override
    public void close() {
        stop();
    }
}
