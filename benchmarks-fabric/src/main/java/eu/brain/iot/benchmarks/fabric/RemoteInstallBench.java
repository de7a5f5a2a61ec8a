package eu.brain.iot.benchmarks.fabric;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/**
 * A remote install on demand: two fabric nodes, each in a JVM of its own with its Gogo shell, joined through a
 * broker. Node B's Bundle Installer reads the probe's signed index ({@code repository/target/probe/}), which offers
 * the probe counter, a behaviour consuming probe events; node A's reads the project's index, which does not. Node A
 * publishes one probe event that nobody consumes: A's Behaviour Management Service holds it and asks the fabric's
 * installer, which chooses node B (the only node offering a behaviour for it); B's installer installs the probe
 * bundle, and the held event reaches the counter's {@code notify()} on B, where its latency is taken (receive time
 * minus the event's {@code sentNanos}, CLOCK_MONOTONIC of the one machine).
 *
 * <p>Repetitions run on the same two nodes: after each, node B uninstalls the probe ({@code bis:uninstall}, then
 * {@code bis:allow} so that the next event may have it installed again) and the next event is published only once
 * node A has seen B's interest in probe events go. So each repetition is one install in a running fabric; the first
 * one after the nodes started (classes loaded and compiled for the first time) is reported apart, not in the
 * percentiles.
 *
 * <p>Threads: the benchmark's thread only.
 */
final class RemoteInstallBench {
    /** One row: the latency of the measured installs, the first install apart. */
    record Row(String what, LatencyStats latency, long firstNanos, String problems) {
    }

    /** The probe bundle's symbolic name: what node B's installer installs, and uninstalls between repetitions. */
    static final String PROBE = "eu.brain.iot.probe";
    /** The probe's event type, which node B's interest names while the probe counter runs there. */
    private static final String PROBE_EVENT = "eu.brain.iot.probe.ProbeEvent";
    private static final long START_TIMEOUT_S = 180;
    /** How long one install may take, from the publication to the counter's latency line. */
    private static final long INSTALL_TIMEOUT_S = 120;
    private static final long SHELL_TIMEOUT_S = 60;
    private static final long POLL_MS = 100;

    private final Settings settings;

    RemoteInstallBench(Settings settings) {
        this.settings = settings;
    }

    /** Null when the indexes and the key the nodes need were built, else what is missing and how to build it. */
    static String missingRepository(Path root) {
        for (Path p : new Path[] {probeIndex(root), projectIndex(root), publicKey(root)}) {
            if (!Files.isRegularFile(p)) {
                return p + " does not exist: build it (mvn -B -pl repository -am package -DskipTests)";
            }
        }
        return null;
    }

    private static Path probeIndex(Path root) {
        return root.resolve("repository/target/probe/index.xml");
    }

    private static Path projectIndex(Path root) {
        return root.resolve("repository/target/repository/index.xml");
    }

    private static Path publicKey(Path root) {
        return root.resolve("repository/target/index-signing.pub");
    }

    Row acrossNodes(String brokerName, BrokerAddress broker) throws Exception {
        Path dir = NodeToNodeBench.fresh(settings.work().resolve("install-" + brokerName.split(" ")[0]
                .toLowerCase()));
        Path key = NodeToNodeBench.fabricKey(dir);
        Path configA = Files.createDirectories(dir.resolve("nodeA/config"));
        Path configB = Files.createDirectories(dir.resolve("nodeB/config"));
        NodeToNodeBench.federationConfig(configA, dir, "nodeA", broker, key);
        NodeToNodeBench.federationConfig(configB, dir, "nodeB", broker, key);
        // A publishes (the probe bundle dropped in, its counter idle without configuration) and installs from the
        // project's index; B installs from the probe's index, and has the counter's configuration ready for it
        new NodeToNodeBench(settings).copyProbe(configA);
        installerConfig(configA, projectIndex(settings.root()));
        installerConfig(configB, probeIndex(settings.root()));
        Files.writeString(configB.resolve("eu.brain.iot.probe.counter.cfg"),
                "file=" + dir.resolve("nodeB/received.txt") + "\n");
        try (NodeProcess b = new NodeProcess("nodeB", settings.root(), dir.resolve("nodeB"), configB, true);
             NodeProcess a = new NodeProcess("nodeA", settings.root(), dir.resolve("nodeA"), configA, true)) {
            b.await(l -> l.startsWith(NodeProcess.READY), 0, START_TIMEOUT_S, "its ready line");
            a.await(l -> l.startsWith(NodeProcess.READY), 0, START_TIMEOUT_S, "its ready line");
            until(a, "fabric:nodes", answer -> answer.matches("(?s).*\\bnodeB\\s+online\\b.*"), "node B online");
            until(b, "fabric:nodes", answer -> answer.matches("(?s).*\\bnodeA\\s+online\\b.*"), "node A online");
            String what = "remote install on demand, " + brokerName;
            StringBuilder problems = new StringBuilder();
            long first = installOnce("install-0", a, configA, b, problems);
            System.err.printf("  %s: first install %s ms (not counted)%n", what, LatencyStats.millis(first));
            long[] nanos = new long[settings.installs()];
            for (int i = 0; i < nanos.length; i++) {
                nanos[i] = installOnce("install-" + (i + 1), a, configA, b, problems);
                System.err.printf("  %s: install %d of %d: %s ms%n", what, i + 1, nanos.length,
                        LatencyStats.millis(nanos[i]));
            }
            return new Row(what, LatencyStats.of(nanos, nanos.length), first, problems.toString());
        }
    }

    /**
     * One probe event published on A, nobody consuming it; returns its latency into the counter's {@code notify()}
     * on B once the installer of B installed the probe; then has B uninstall it and waits until A knows.
     */
    private static long installOnce(String run, NodeProcess a, Path configA, NodeProcess b, StringBuilder problems)
            throws Exception {
        int fromA = a.lineCount();
        int fromB = b.lineCount();
        Files.writeString(configA.resolve("eu.brain.iot.probe.publisher-" + run + ".cfg"), "run=" + run
                + "\ncount=1\nrate=0\nconsumer.timeout.s=0\n");
        String published = a.await(l -> l.contains("probe publisher: run=" + run + " "), fromA, INSTALL_TIMEOUT_S,
                "the publication of run " + run);
        if (!published.contains(" published=")) {
            throw new IOException(published);
        }
        String latency = b.await(l -> l.contains("probe latency: run=" + run + " "), fromB, INSTALL_TIMEOUT_S,
                "the probe's latency of run " + run + " (installed on demand)");
        Map<String, Long> f = NodeToNodeBench.fields(latency);
        String counts = b.last(l -> l.contains("probe counter: run=" + run + " "), fromB)
                .orElseThrow(() -> new IOException("nodeB printed no counts for run " + run));
        Map<String, Long> c = NodeToNodeBench.fields(counts);
        if (c.get("received") != 1 || c.get("duplicates") != 0) {
            problems.append(run).append(": ").append(counts.substring(counts.indexOf("probe counter:"))).append("; ");
        }
        String removed = b.ask("bis:uninstall " + PROBE, SHELL_TIMEOUT_S);
        if (!removed.contains("uninstalled")) {
            throw new IOException("nodeB did not uninstall the probe after run " + run + ": " + removed.strip());
        }
        String allowed = b.ask("bis:allow " + PROBE, SHELL_TIMEOUT_S);
        if (!allowed.contains("may be installed automatically again")) {
            throw new IOException("nodeB did not allow the probe again after run " + run + ": " + allowed.strip());
        }
        until(a, "fabric:interest nodeB", answer -> answer.contains("nodeB (") && !answer.contains(PROBE_EVENT),
                "node B's interest in probe events gone after run " + run);
        return f.get("p50Ns");
    }

    /** Asks the node's shell again until the answer fits, up to the shell's time-out. */
    private static void until(NodeProcess node, String command, Predicate<String> answer, String what)
            throws IOException, InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(SHELL_TIMEOUT_S);
        String last = node.ask(command, SHELL_TIMEOUT_S);
        while (!answer.test(last)) {
            if (System.nanoTime() > deadline) {
                throw new IOException(node.name() + ": no " + what + " within " + SHELL_TIMEOUT_S + " s; '" + command
                        + "' answers: " + last.strip());
            }
            Thread.sleep(POLL_MS); // asks the shell again: the node signals nothing the benchmark could wait on
            last = node.ask(command, SHELL_TIMEOUT_S);
        }
    }

    /** The node's Bundle Installer (PID {@code eu.brain.iot.bis}): this index, trusted by the build's key. */
    private void installerConfig(Path config, Path index) throws IOException {
        Files.writeString(config.resolve("eu.brain.iot.bis.cfg"), "repositories=" + index + "\ntrusted.keys="
                + publicKey(settings.root()) + "\n");
    }
}
