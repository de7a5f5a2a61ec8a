package eu.brain.iot.benchmarks;

import java.io.IOException;
import java.io.InputStream;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Runs one contender in a JVM of its own, as JMH forks each benchmark. Measured here in one JVM: our bus reached
 * 2.5 M events/s with 8 consumers when it ran first and 1.1 M when it ran after the three peers, whose frameworks
 * had left their type profiles on the JDK classes every bus uses (queues, locks, thread parking). A fresh JVM per
 * contender gives each the same start; the launching JVM only collects the results and prints the table.
 * <p>
 * The forked JVM gets this JVM's options (heap, GC, {@code -XX} flags) and class path, the same settings, one
 * contender, and a file to write its {@link ContenderResult} to (Java serialisation: both ends are this jar).
 */
final class ForkedRun {

    /** The internal option that makes a JVM a forked one: the file for its result. */
    static final String RESULT_OPTION = "--result-to";

    private static final List<String> OWN_OPTIONS = List.of("--contenders", "--fork", RESULT_OPTION);

    private ForkedRun() {
    }

    /** In the launching JVM: run {@code contender} in a fresh JVM and read back what it measured. */
    static ContenderResult run(Contender contender, String[] args) {
        Path result = null;
        try {
            result = Files.createTempFile("bus-benchmark-" + contender.key() + "-", ".result");
            List<String> command = new ArrayList<>();
            command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
            for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
                if (!option.startsWith("-agentlib:jdwp")) { // a debugger's port is this JVM's alone
                    command.add(option);
                }
            }
            command.addAll(List.of("-cp", System.getProperty("java.class.path"), BusBenchmark.class.getName()));
            command.addAll(withoutOwnOptions(args));
            command.addAll(List.of("--contenders", contender.key(), RESULT_OPTION, result.toString()));
            // The forked JVM's progress goes to our standard error; it prints nothing on standard output.
            Process process = new ProcessBuilder(command).redirectOutput(ProcessBuilder.Redirect.INHERIT)
                    .redirectError(ProcessBuilder.Redirect.INHERIT).start();
            // A launcher stopped by Ctrl-C or kill must not leave a benchmark JVM busy on the cores.
            Thread stopChild = new Thread(process::destroyForcibly, "stop-forked-benchmark");
            Runtime.getRuntime().addShutdownHook(stopChild);
            int exit;
            try {
                exit = process.waitFor();
            } finally {
                try {
                    Runtime.getRuntime().removeShutdownHook(stopChild);
                } catch (IllegalStateException e) {
                    // the launcher is shutting down already: the hook stops the child
                }
            }
            if (Files.size(result) == 0) {
                return ContenderResult.failed(contender, "the forked JVM ended (exit code " + exit
                        + ") without a result; its messages are above");
            }
            try (InputStream in = Files.newInputStream(result); ObjectInputStream objects = new ObjectInputStream(in)) {
                return (ContenderResult) objects.readObject();
            }
        } catch (IOException | ClassNotFoundException e) {
            return ContenderResult.failed(contender, "could not run it in a forked JVM: " + e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return ContenderResult.failed(contender, "interrupted while its forked JVM ran");
        } finally {
            if (result != null) {
                try {
                    Files.deleteIfExists(result);
                } catch (IOException e) {
                    // a temporary file left behind: nothing to report
                }
            }
        }
    }

    /** In a forked JVM: hand the result to the launching JVM. */
    static void write(ContenderResult result, Path file) throws IOException {
        try (OutputStream out = Files.newOutputStream(file); ObjectOutputStream objects = new ObjectOutputStream(out)) {
            objects.writeObject(result);
        }
    }

    private static List<String> withoutOwnOptions(String[] args) {
        List<String> kept = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            if (OWN_OPTIONS.contains(args[i])) {
                i++; // and its value
            } else {
                kept.add(args[i]);
            }
        }
        return kept;
    }
}
