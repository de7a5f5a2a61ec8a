package eu.brain.iot.benchmarks.fabric;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.HashMap;
import java.util.Map;
import java.util.zip.ZipFile;

/**
 * Node to node: two fabric nodes, each in a JVM of its own, joined through a broker (the federation's
 * configuration, PID {@code eu.brain.iot.federation}); the probe publisher on node A, the probe counter on node B
 * (the probe bundle, {@code fabric-probe/target/fabric-probe.jar}, dropped into both configuration folders). Events
 * are counted, and their latency taken, inside the counter's {@code notify()}. The same with one node and no broker
 * (publisher and counter on one bus) gives the local bus's row.
 */
final class NodeToNodeBench {
    /** One row: events per second back to back, latency at the paced rate. */
    record Row(String what, double eventsPerSecond, LatencyStats paced, String problems) {
    }

    private static final long START_TIMEOUT_S = 180;
    private static final long RUN_TIMEOUT_S = 300;
    private static final int KEY_BYTES = 32;
    /** Seconds of each paced warm-up run after the first. */
    static final int WARM_STEP_S = 5;
    /** The compilers' share of one core under which the JVMs count as warm. */
    static final double JIT_QUIET_SHARE = 0.03;
    /** The counter keeps its counts in memory: a file write inside {@code notify()} would be measured as latency. */
    private static final String COUNTS_IN_MEMORY = "file=\n";

    private final Settings settings;

    NodeToNodeBench(Settings settings) {
        this.settings = settings;
    }

    /** Null when the node's jar runs the federation bundle, else why the node-to-node runs cannot be made. */
    static String missingFederation(Path root) {
        Path jar = root.resolve("node/target/fabric-node.jar");
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            return zip.stream().anyMatch(e -> e.getName().matches("jar/federation[^/]*\\.jar")) ? null
                    : jar + " holds no federation bundle";
        } catch (IOException e) {
            return "cannot read " + jar + ": " + e.getMessage();
        }
    }

    /** Node A publishes, node B counts, through the broker. */
    Row acrossNodes(String brokerName, BrokerAddress broker) throws Exception {
        Path dir = fresh(settings.work().resolve("nodes-" + brokerName.split(" ")[0].toLowerCase()));
        Path key = fabricKey(dir);
        Path configB = nodeConfig(dir, "nodeB", broker, key, true);
        Path configA = nodeConfig(dir, "nodeA", broker, key, false);
        try (NodeProcess b = new NodeProcess("nodeB", settings.root(), dir.resolve("nodeB"), configB);
             NodeProcess a = new NodeProcess("nodeA", settings.root(), dir.resolve("nodeA"), configA)) {
            b.await(l -> l.startsWith(NodeProcess.READY), 0, START_TIMEOUT_S, "its ready line");
            a.await(l -> l.startsWith(NodeProcess.READY), 0, START_TIMEOUT_S, "its ready line");
            b.await(l -> l.startsWith("probe counter: ready"), 0, START_TIMEOUT_S, "the probe counter's ready line");
            return measure("node to node, " + brokerName, a, configA, b);
        }
    }

    /** Publisher and counter on one node's bus, no broker. */
    Row localBus() throws Exception {
        Path dir = fresh(settings.work().resolve("local"));
        Path config = Files.createDirectories(dir.resolve("node/config"));
        copyProbe(config);
        Files.writeString(config.resolve("eu.brain.iot.probe.counter.cfg"), COUNTS_IN_MEMORY);
        try (NodeProcess n = new NodeProcess("local", settings.root(), dir.resolve("node"), config)) {
            n.await(l -> l.startsWith("probe counter: ready"), 0, START_TIMEOUT_S, "the probe counter's ready line");
            return measure("local bus (one node)", n, config, n);
        }
    }

    private Row measure(String what, NodeProcess publisher, Path publisherConfig, NodeProcess counter)
            throws Exception {
        StringBuilder problems = new StringBuilder();
        run("warm", settings.floodWarmup(), 0, publisher, publisherConfig, counter, problems);
        Map<String, Long> flood = run("flood", settings.floodMessages(), 0, publisher, publisherConfig, counter,
                problems);
        double perSecond = settings.floodMessages() * 1e9 / (flood.get("lastNs") - flood.get("startNs"));
        System.err.printf("  %s: %,.0f events/s back to back%n", what, perSecond);
        int rate = settings.rate();
        warmUntilTheJitIsQuiet(what, rate, publisher, publisherConfig, counter, problems);
        Map<String, Long> paced = run("paced", (long) (rate * settings.latencySeconds()), rate, publisher,
                publisherConfig, counter, problems);
        LatencyStats latency = new LatencyStats(paced.get("n").intValue(), paced.get("p50Ns"), paced.get("p99Ns"),
                paced.get("maxNs"));
        System.err.printf("  %s at %,d/s: p50 %s ms, p99 %s ms%n", what, rate, LatencyStats.millis(latency.p50Nanos()),
                LatencyStats.millis(latency.p99Nanos()));
        return new Row(what, perSecond, latency, problems.toString());
    }

    /**
     * Paced runs not measured: the minimum warm-up, then more of {@link #WARM_STEP_S} each while the JIT compilers of
     * the benchmark's JVMs used more than {@link #JIT_QUIET_SHARE} of one core during the last, up to the maximum.
     */
    private void warmUntilTheJitIsQuiet(String what, int rate, NodeProcess publisher, Path config,
            NodeProcess counter, StringBuilder problems) throws Exception {
        JitActivity jit = JitActivity.available() ? new JitActivity() : null;
        run("pacedwarm", (long) (rate * settings.latencyWarmupSeconds()), rate, publisher, config, counter, problems);
        double warmed = settings.latencyWarmupSeconds();
        double share = jit == null ? 0 : jit.shareSinceLast();
        for (int round = 2; share > JIT_QUIET_SHARE && warmed < settings.latencyWarmupMaxSeconds(); round++) {
            run("pacedwarm" + round, rate * WARM_STEP_S, rate, publisher, config, counter, problems);
            warmed += WARM_STEP_S;
            share = jit.shareSinceLast();
        }
        System.err.printf("  %s: paced warm-up %.0f s, %s%n", what, warmed, jit == null
                ? "no JIT activity to read here (Linux's /proc)"
                : String.format("the JIT compilers at %.1f%% of one core in its last seconds%s", share * 100,
                        share > JIT_QUIET_SHARE ? " (still busy at --latency-warmup-max)" : ""));
    }

    /** Starts one run and waits for the counter's latency line; the figures of that line and the start time. */
    private static Map<String, Long> run(String run, long count, int rate, NodeProcess publisher, Path config,
            NodeProcess counter, StringBuilder problems) throws Exception {
        int fromPublisher = publisher.lineCount();
        int fromCounter = counter.lineCount();
        Files.writeString(config.resolve("eu.brain.iot.probe.publisher-" + run + ".cfg"),
                "run=" + run + "\ncount=" + count + "\nrate=" + rate + "\n");
        String published = publisher.await(l -> l.startsWith("probe publisher: run=" + run + " ")
                && !l.endsWith(" consumer known"), fromPublisher, RUN_TIMEOUT_S, "the end of run " + run);
        if (!published.contains(" published=")) {
            throw new IOException(published);
        }
        String latency = counter.await(l -> l.startsWith("probe latency: run=" + run + " ") && fields(l).get("n")
                >= count, fromCounter, RUN_TIMEOUT_S, "the latency of run " + run + " (" + count + " events)");
        Map<String, Long> f = fields(latency);
        f.put("startNs", fields(published).get("startNs"));
        String counts = counter.last(l -> l.startsWith("probe counter: run=" + run + " "), fromCounter)
                .orElseThrow(() -> new IOException(counter.name() + " printed no counts for run " + run));
        Map<String, Long> c = fields(counts);
        if (c.get("distinct") != count || c.get("duplicates") != 0 || c.get("outOfOrder") != 0) {
            problems.append(run).append(": ").append(counts).append("; ");
        }
        return f;
    }

    /** The numeric {@code key=value} fields of a probe line. */
    static Map<String, Long> fields(String line) {
        Map<String, Long> f = new HashMap<>();
        for (String part : line.split(" ")) {
            int eq = part.indexOf('=');
            if (eq > 0 && part.substring(eq + 1).matches("-?\\d+")) {
                f.put(part.substring(0, eq), Long.parseLong(part.substring(eq + 1)));
            }
        }
        return f;
    }

    /** A fabric key made for the run ({@code fabric.key} in the folder), 32 random bytes in base64. */
    static Path fabricKey(Path dir) throws IOException {
        Path key = dir.resolve("fabric.key");
        byte[] secret = new byte[KEY_BYTES];
        new SecureRandom().nextBytes(secret);
        Files.writeString(key, Base64.getEncoder().encodeToString(secret) + "\n");
        return key;
    }

    /** The federation's configuration of a node (fabric {@code bench}) into its configuration folder. */
    static void federationConfig(Path config, Path dir, String node, BrokerAddress broker, Path key)
            throws IOException {
        Files.writeString(config.resolve("eu.brain.iot.federation.cfg"), "broker.uri=" + broker.uri()
                + "\nfabric.name=bench\nnode.name=" + node + "\nkey.file=" + key + "\nstate.dir="
                + dir.resolve(node).resolve("federation") + "\n", StandardCharsets.UTF_8);
    }

    private Path nodeConfig(Path dir, String node, BrokerAddress broker, Path key, boolean counts) throws IOException {
        Path config = Files.createDirectories(dir.resolve(node).resolve("config"));
        copyProbe(config);
        federationConfig(config, dir, node, broker, key);
        if (counts) {
            Files.writeString(config.resolve("eu.brain.iot.probe.counter.cfg"), COUNTS_IN_MEMORY);
        }
        return config;
    }

    void copyProbe(Path config) throws IOException {
        Path probe = settings.root().resolve("fabric-probe/target/fabric-probe.jar");
        if (!Files.isRegularFile(probe)) {
            throw new IOException(probe + " does not exist: build it (mvn -B -pl fabric-probe -am package)");
        }
        Files.copy(probe, config.resolve("fabric-probe.jar"), StandardCopyOption.REPLACE_EXISTING);
    }

    static Path fresh(Path dir) throws IOException {
        if (Files.exists(dir)) {
            try (var files = Files.walk(dir)) {
                for (Path p : files.sorted(java.util.Comparator.reverseOrder()).toList()) {
                    Files.delete(p);
                }
            }
        }
        return Files.createDirectories(dir);
    }
}
