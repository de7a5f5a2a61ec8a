package eu.brain.iot.benchmarks.fabric;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/**
 * A fabric node in a JVM of its own ({@code java -jar node/target/fabric-node.jar}), its own home
 * ({@code -Duser.home}), state folder ({@code -Dfabric.node.state}), HTTP port and configuration folder; its edge
 * polls nothing (port 9). Without a shell, or with the Gogo shell reading the commands {@link #ask} types into its
 * standard input. Its output is kept line by line (and written to {@code node.log} in its folder) for the benchmark to
 * wait on.
 *
 * <p>Threads: the benchmark thread starts, types, waits and stops; one reader thread appends the lines.
 */
final class NodeProcess implements AutoCloseable {
    static final String READY = "fabric node ready in";
    private static final long POLL_MS = 50;

    private final String name;
    private final Process process;
    private final List<String> lines = new CopyOnWriteArrayList<>();
    private final Writer shell;
    private int asked;

    /** A node without a shell. */
    NodeProcess(String name, Path root, Path folder, Path configDir) throws IOException {
        this(name, root, folder, configDir, false);
    }

    /** A node with the Gogo shell on its standard input when {@code withShell}, else without one. */
    NodeProcess(String name, Path root, Path folder, Path configDir, boolean withShell) throws IOException {
        this.name = name;
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path home = Files.createDirectories(folder.resolve("home"));
        List<String> command = new ArrayList<>(List.of(java.toString(), "-Xms512m", "-Xmx512m",
                "-Duser.home=" + home, "-Dfabric.node.state=" + folder.resolve("state"), "-Dfabric.node.name=" + name,
                "-Dfabric.node.root=" + root, "-Dorg.osgi.service.http.port=" + BrokerProcess.freePort(),
                "-Dfelix.fileinstall.dir=" + configDir, "-Deu.brain.iot.edge.fleet.url=http://127.0.0.1:9/",
                "-jar", root.resolve("node/target/fabric-node.jar").toString()));
        if (!withShell) {
            command.add(1, "-Dgosh.args=--nointeractive");
        }
        process = new ProcessBuilder(command).redirectErrorStream(true).start();
        shell = withShell ? process.outputWriter(StandardCharsets.UTF_8) : null;
        PrintWriter log = new PrintWriter(Files.newBufferedWriter(folder.resolve("node.log")), true);
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8)); log) {
                for (String l = r.readLine(); l != null; l = r.readLine()) {
                    lines.add(l);
                    log.println(l);
                }
            } catch (IOException e) {
                lines.add("(reading " + name + "'s output failed: " + e + ")");
            }
        }, name + "-output");
        reader.setDaemon(true);
        reader.start();
    }

    /** The first line (from the {@code from}-th on) that matches, waiting up to the time-out while the node lives. */
    String await(Predicate<String> line, int from, long timeoutS, String what) throws IOException,
            InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutS);
        while (true) {
            for (int i = from; i < lines.size(); i++) {
                if (line.test(lines.get(i))) {
                    return lines.get(i);
                }
            }
            if (!process.isAlive() || System.nanoTime() > deadline) {
                throw new IOException(name + (process.isAlive() ? " did not print " + what + " within " + timeoutS
                        + " s" : " ended before printing " + what) + "; its last lines: "
                        + lines.subList(Math.max(0, lines.size() - 15), lines.size()));
            }
            Thread.sleep(POLL_MS); // polls the collected output: the reader thread signals nothing
        }
    }

    /**
     * Types a command into the node's shell and returns what it printed: the lines up to an {@code echo} of a marker
     * typed after it (the shell runs one line at a time), waiting up to the time-out.
     */
    String ask(String command, long timeoutS) throws IOException, InterruptedException {
        if (shell == null) {
            throw new IllegalStateException(name + " was started without a shell");
        }
        int from = lines.size();
        String marker = "asked-" + (++asked) + "-done";
        shell.write(command + "\n" + "echo " + marker + "\n");
        shell.flush();
        // the shell may echo what it reads: the marker counts only as echo's output
        Predicate<String> end = l -> l.contains(marker) && !l.contains("echo ");
        await(end, from, timeoutS, "the answer to '" + command + "'");
        StringBuilder out = new StringBuilder();
        for (int i = from; i < lines.size() && !end.test(lines.get(i)); i++) {
            out.append(lines.get(i)).append('\n');
        }
        return out.toString();
    }

    /** The last line (from the {@code from}-th on) that matches, as printed so far. */
    java.util.Optional<String> last(Predicate<String> line, int from) {
        String found = null;
        for (int i = from; i < lines.size(); i++) {
            if (line.test(lines.get(i))) {
                found = lines.get(i);
            }
        }
        return java.util.Optional.ofNullable(found);
    }

    int lineCount() {
        return lines.size();
    }

    String name() {
        return name;
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
        }
    }
}
