package eu.brain.iot.benchmarks.fabric;

import java.nio.file.Path;
import java.util.List;

/**
 * The benchmark's command line.
 *
 * @param parts                what to measure: {@code bare} (two bare clients), {@code nodes} (node to node),
 *                             {@code install} (a remote install on demand), {@code local} (the local bus of one node)
 * @param brokers              which brokers, in order: {@code embedded}, {@code embedded-file},
 *                             {@code mosquitto}
 * @param mosquittoUri         a Mosquitto already running (null: the benchmark starts Debian's on a free port)
 * @param floodMessages        messages measured back to back
 * @param floodWarmup          messages sent first and not measured
 * @param rate                 the paced rate of the latency runs, messages (events) per second
 * @param latencyWarmupSeconds paced seconds not measured, at least
 * @param latencyWarmupMaxSeconds paced seconds not measured, at most: node to node warms up until the JIT compilers
 *                             are quiet ({@link JitActivity})
 * @param latencySeconds       paced seconds measured
 * @param installs             remote installs measured (after a first one, not measured)
 * @param root                 the checkout (broker/target/broker.jar)
 * @param work                 scratch folder (brokers' state and logs)
 */
record Settings(List<String> parts, List<String> brokers, String mosquittoUri, int floodMessages, int floodWarmup, int rate,
        double latencyWarmupSeconds, double latencyWarmupMaxSeconds, double latencySeconds, int installs, Path root,
        Path work) {

    /** What {@code --parts} takes, in the order of the table. */
    static final List<String> PARTS = List.of("bare", "nodes", "install", "local");
    static final String EMBEDDED = "embedded";
    static final String EMBEDDED_FILE = "embedded-file";
    static final String MOSQUITTO = "mosquitto";
    static final List<String> BROKERS = List.of(EMBEDDED, EMBEDDED_FILE, MOSQUITTO);

    static final String USAGE = """
            Usage: java -jar benchmarks-fabric/target/fabric-bench.jar [options]
              --parts LIST          bare,nodes,install,local (default all: two bare MQTT clients, node to node, a
                                    remote install on demand, one node's local bus); node to node and the remote
                                    install need the federation bundle in node/target/fabric-node.jar
              --brokers LIST        embedded,mosquitto (default both, in that order); embedded is the broker as
                                    ./fabric-node --nodes runs it (in memory), embedded-file with its sessions and
                                    queued messages in files (the broker's own default)
              --mosquitto-uri URI   a running Mosquitto (default: start Debian's /usr/sbin/mosquitto on a free port)
              --messages N          messages measured back to back (default 200000)
              --warmup N            messages sent before them, not measured (default 50000)
              --rate N              paced rate of the latency runs, per second (default 2000)
              --latency-warmup S    paced seconds not measured (default 3); node to node goes on warming up,
                                    5 s at a time, while the JVMs' JIT compilers take over 3% of a core
              --latency-warmup-max S  at most this many (default 120)
              --latency-seconds S   paced seconds measured (default 10)
              --installs N          remote installs measured, after a first one not measured (default 20)
              --root DIR            the checkout (default .)
              --work DIR            scratch folder (default benchmarks-fabric/target/run)
            """;

    static Settings parse(String[] args) {
        List<String> parts = PARTS;
        List<String> brokers = List.of(EMBEDDED, MOSQUITTO);
        String mosquitto = null;
        int messages = 200_000;
        int warmup = 50_000;
        int rate = 2000;
        double latencyWarmup = 3;
        double latencyWarmupMax = 120;
        double latency = 10;
        int installs = 20;
        Path root = Path.of(".");
        Path work = null;
        for (int i = 0; i < args.length; i++) {
            String flag = args[i];
            if (i + 1 >= args.length) {
                throw new IllegalArgumentException(flag + " needs a value (or is unknown)");
            }
            String v = args[++i];
            switch (flag) {
                case "--parts" -> parts = List.of(v.split(","));
                case "--brokers" -> brokers = List.of(v.split(","));
                case "--mosquitto-uri" -> mosquitto = BrokerAddress.parse(v).uri();
                case "--messages" -> messages = positive(flag, v);
                case "--warmup" -> warmup = positive(flag, v);
                case "--rate" -> rate = positive(flag, v);
                case "--latency-warmup" -> latencyWarmup = positive(flag, v);
                case "--latency-warmup-max" -> latencyWarmupMax = positive(flag, v);
                case "--latency-seconds" -> latency = positive(flag, v);
                case "--installs" -> installs = positive(flag, v);
                case "--root" -> root = Path.of(v);
                case "--work" -> work = Path.of(v);
                default -> throw new IllegalArgumentException("unknown option " + flag);
            }
        }
        for (String b : brokers) {
            if (!BROKERS.contains(b)) {
                throw new IllegalArgumentException("--brokers takes " + String.join(", ", BROKERS) + ", found '" + b
                        + "'");
            }
        }
        for (String p : parts) {
            if (!PARTS.contains(p)) {
                throw new IllegalArgumentException("--parts takes " + String.join(", ", PARTS) + ", found '" + p
                        + "'");
            }
        }
        root = root.toAbsolutePath().normalize();
        return new Settings(parts, brokers, mosquitto, messages, warmup, rate, latencyWarmup,
                Math.max(latencyWarmup, latencyWarmupMax), latency, installs, root,
                (work == null ? root.resolve("benchmarks-fabric/target/run") : work).toAbsolutePath());
    }

    private static int positive(String flag, String v) {
        try {
            int n = Integer.parseInt(v);
            if (n > 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException(flag + " needs a whole number above 0, found '" + v + "'");
    }
}
