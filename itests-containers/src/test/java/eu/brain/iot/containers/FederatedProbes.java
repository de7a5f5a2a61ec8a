package eu.brain.iot.containers;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.testcontainers.images.builder.Transferable;

/**
 * What the cross-node tests give a node: the federation's configuration (PID {@code eu.brain.iot.federation}), the
 * fabric's key, the probe bundle ({@code fabric-probe/target/fabric-probe.jar}), and the probes'
 * configurations; and the counter's lines read back from a node's output.
 */
final class FederatedProbes {
    static final String FABRIC = "itest";
    static final String KEY_PATH = "/app/fabric.key";
    static final String PROBE_BUNDLE_PATH = FabricContainers.CONFIG_DIR + "probe.jar";
    static final String COUNTER_FILE = "/root/probe/received.txt";
    private static final Pattern COUNTER_LINE = Pattern.compile(
            "^probe counter: run=(\\S+) received=(\\d+) distinct=(\\d+) duplicates=(\\d+) outOfOrder=(\\d+) last=(\\d+)",
            Pattern.MULTILINE);

    /** One run's counts as the counter last printed them. */
    record Counts(String run, long received, long distinct, long duplicates, long outOfOrder, long last) {
    }

    private final byte[] key;
    private final Path probeBundle;

    FederatedProbes() {
        byte[] secret = new byte[32];
        new SecureRandom().nextBytes(secret);
        key = (Base64.getEncoder().encodeToString(secret) + "\n").getBytes(StandardCharsets.US_ASCII);
        probeBundle = Path.of(System.getProperty("containers.probe.bundle", "../fabric-probe/target/fabric-probe.jar"));
        if (!Files.isRegularFile(probeBundle)) {
            throw new IllegalStateException("the probe bundle " + probeBundle + " does not exist: build it "
                    + "(mvn -pl itests-containers -am verify builds it first)");
        }
    }

    /** The configuration files of a node of the fabric through {@code broker:1883}. */
    Map<String, String> configFiles(String node, boolean counts) {
        Map<String, String> files = new LinkedHashMap<>();
        files.put("eu.brain.iot.federation.cfg", String.join("\n", List.of(
                "broker.uri=" + FabricContainers.brokerUriInNetwork(), "fabric.name=" + FABRIC, "node.name=" + node,
                "key.file=" + KEY_PATH, "")));
        if (counts) {
            files.put("eu.brain.iot.probe.counter.cfg", "file=" + COUNTER_FILE + "\n");
        }
        return files;
    }

    /** The key (mode 600) alone. */
    Map<String, Transferable> keyFile() {
        return Map.of(KEY_PATH, Transferable.of(key, 0600));
    }

    /** The key (mode 600) and the probe bundle. */
    Map<String, Transferable> files() throws IOException {
        Map<String, Transferable> files = new LinkedHashMap<>(keyFile());
        files.put(PROBE_BUNDLE_PATH, Transferable.of(Files.readAllBytes(probeBundle), 0644));
        return files;
    }

    /** A publishing run's configuration: its file name in the configuration folder (a factory configuration). */
    static String publisherFile(String run) {
        return "eu.brain.iot.probe.publisher-" + run + ".cfg";
    }

    static String publisherConfig(String run, long count, int rate) {
        return "run=" + run + "\ncount=" + count + "\nrate=" + rate + "\n";
    }

    /** The counter's last line for the run in this output. */
    static Optional<Counts> lastCounts(String logs, String run) {
        Matcher m = COUNTER_LINE.matcher(logs);
        Counts last = null;
        while (m.find()) {
            if (m.group(1).equals(run)) {
                last = new Counts(run, Long.parseLong(m.group(2)), Long.parseLong(m.group(3)),
                        Long.parseLong(m.group(4)), Long.parseLong(m.group(5)), Long.parseLong(m.group(6)));
            }
        }
        return Optional.ofNullable(last);
    }
}
