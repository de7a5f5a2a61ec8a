package eu.brain.iot.benchmarks.fabric;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code java -jar benchmarks-fabric/target/fabric-bench.jar}: for each broker, two bare MQTT 5 clients with QoS 1
 * (throughput, and latency at the paced rate). Prints a Markdown table on standard output, progress on standard
 * error. Exit code 2 for a bad command line, 1 when a broker or a run failed.
 */
public final class FabricBench {
    private FabricBench() {
    }

    public static void main(String[] args) throws Exception {
        if (List.of(args).contains("--help")) {
            System.out.print(Settings.USAGE);
            return;
        }
        Settings settings;
        try {
            settings = Settings.parse(args);
        } catch (IllegalArgumentException e) {
            System.err.println("fabric-bench: " + e.getMessage());
            System.err.print(Settings.USAGE);
            System.exit(2);
            return;
        }
        Files.createDirectories(settings.work());
        List<BareClientsBench.Row> rows = new ArrayList<>();
        for (String broker : settings.brokers()) {
            try {
                rows.add(runOn(broker, settings));
            } catch (Exception e) {
                System.err.println("fabric-bench: the runs through " + broker + " failed: " + e.getMessage());
                System.exit(1);
            }
        }
        System.out.println();
        System.out.printf("| broker | bare clients, QoS 1: messages/s | p50 at %,d/s (ms) | p99 (ms) | max (ms) |%n",
                settings.rate());
        System.out.println("|---|---:|---:|---:|---:|");
        for (BareClientsBench.Row r : rows) {
            System.out.printf("| %s | %,.0f | %s | %s | %s |%n", r.broker(), r.messagesPerSecond(),
                    LatencyStats.millis(r.paced().latency().p50Nanos()),
                    LatencyStats.millis(r.paced().latency().p99Nanos()),
                    LatencyStats.millis(r.paced().latency().maxNanos()));
        }
        for (BareClientsBench.Row r : rows) {
            for (ForkedSubscriber.Result res : List.of(r.flood(), r.paced())) {
                if (!res.complete() || res.duplicates() > 0 || res.outOfOrder() > 0) {
                    System.out.printf("note: %s: %,d received, complete %s, %d duplicates, %d out of order%n",
                            r.broker(), res.received(), res.complete(), res.duplicates(), res.outOfOrder());
                }
            }
        }
    }

    private static BareClientsBench.Row runOn(String broker, Settings settings) throws Exception {
        if (broker.equals("mosquitto") && settings.mosquittoUri() != null) {
            return new BareClientsBench(settings).run("Mosquitto " + settings.mosquittoUri(),
                    BrokerAddress.parse(settings.mosquittoUri()));
        }
        try (BrokerProcess b = broker.equals("embedded") ? BrokerProcess.embedded(settings.root(), settings.work())
                : BrokerProcess.mosquitto(settings.work())) {
            System.err.println("fabric-bench: " + b.name() + " at " + b.address().uri());
            return new BareClientsBench(settings).run(b.name(), b.address());
        }
    }
}
