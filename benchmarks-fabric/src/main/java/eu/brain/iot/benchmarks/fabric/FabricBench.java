package eu.brain.iot.benchmarks.fabric;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code java -jar benchmarks-fabric/target/fabric-bench.jar}: for each broker, two bare MQTT 5 clients with QoS 1,
 * two fabric nodes (each in its own JVM) through it, and a remote install on demand between two such nodes; and one
 * node's local bus. Each: events (messages) per second back to back, and latency at the paced rate; for the installs,
 * the latency of each install's one event. Prints Markdown tables on standard output, progress on standard error.
 * Exit code 2 for a bad command line, 1 when a broker or a run failed.
 */
public final class FabricBench {
    /** One line of the table. */
    private record Line(String what, double perSecond, LatencyStats latency, String problems) {
    }

    /** The results of every part, in the order they were measured. */
    private record Results(List<Line> lines, List<RemoteInstallBench.Row> installs) {
    }

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
        boolean twoNodeParts = settings.parts().contains("nodes") || settings.parts().contains("install");
        String noFederation = twoNodeParts ? NodeToNodeBench.missingFederation(settings.root()) : null;
        if (noFederation != null) {
            System.err.println("fabric-bench: node to node and the remote install skipped: " + noFederation);
        }
        String noIndex = settings.parts().contains("install") && noFederation == null
                ? RemoteInstallBench.missingRepository(settings.root()) : null;
        if (noIndex != null) {
            System.err.println("fabric-bench: the remote install skipped: " + noIndex);
        }
        Results results = new Results(new ArrayList<>(), new ArrayList<>());
        List<Line> lines = results.lines();
        try {
            boolean nodes = settings.parts().contains("nodes") && noFederation == null;
            boolean install = settings.parts().contains("install") && noFederation == null && noIndex == null;
            if (settings.parts().contains("bare") || nodes || install) {
                for (String broker : settings.brokers()) {
                    runOn(broker, settings, nodes, install, results);
                }
            }
            if (settings.parts().contains("local")) {
                NodeToNodeBench.Row r = new NodeToNodeBench(settings).localBus();
                lines.add(new Line(r.what(), r.eventsPerSecond(), r.paced(), r.problems()));
            }
        } catch (Exception e) {
            System.err.println("fabric-bench: a run failed: " + e.getMessage());
            System.exit(1);
        }
        if (!lines.isEmpty()) {
            System.out.println();
            System.out.printf("| what | per second, back to back | p50 at %,d/s (ms) | p99 (ms) | max (ms) |%n",
                    settings.rate());
            System.out.println("|---|---:|---:|---:|---:|");
            for (Line l : lines) {
                System.out.printf("| %s | %,.0f | %s | %s | %s |%n", l.what(), l.perSecond(),
                        LatencyStats.millis(l.latency().p50Nanos()), LatencyStats.millis(l.latency().p99Nanos()),
                        LatencyStats.millis(l.latency().maxNanos()));
            }
        }
        if (!results.installs().isEmpty()) {
            System.out.println();
            System.out.println("| what (first event → the remote behaviour's notify) | installs | first (ms) | p50 (ms)"
                    + " | p99 (ms) | max (ms) |");
            System.out.println("|---|---:|---:|---:|---:|---:|");
            for (RemoteInstallBench.Row r : results.installs()) {
                System.out.printf("| %s | %d | %s | %s | %s | %s |%n", r.what(), r.latency().samples(),
                        LatencyStats.millis(r.firstNanos()), LatencyStats.millis(r.latency().p50Nanos()),
                        LatencyStats.millis(r.latency().p99Nanos()), LatencyStats.millis(r.latency().maxNanos()));
            }
        }
        for (Line l : lines) {
            if (!l.problems().isEmpty()) {
                System.out.println("note: " + l.what() + ": " + l.problems());
            }
        }
        for (RemoteInstallBench.Row r : results.installs()) {
            if (!r.problems().isEmpty()) {
                System.out.println("note: " + r.what() + ": " + r.problems());
            }
        }
    }

    private static void runOn(String broker, Settings settings, boolean nodes, boolean install, Results results)
            throws Exception {
        if (broker.equals(Settings.MOSQUITTO) && settings.mosquittoUri() != null) {
            runOn("Mosquitto " + settings.mosquittoUri(), BrokerAddress.parse(settings.mosquittoUri()), settings,
                    nodes, install, results);
            return;
        }
        try (BrokerProcess b = broker.equals(Settings.MOSQUITTO) ? BrokerProcess.mosquitto(settings.work())
                : BrokerProcess.embedded(settings.root(), settings.work(),
                        !broker.equals(Settings.EMBEDDED_FILE))) {
            System.err.println("fabric-bench: " + b.name() + " at " + b.address().uri());
            runOn(b.name(), b.address(), settings, nodes, install, results);
        }
    }

    private static void runOn(String name, BrokerAddress address, Settings settings, boolean nodes, boolean install,
            Results results) throws Exception {
        List<Line> lines = results.lines();
        if (settings.parts().contains("bare")) {
            BareClientsBench.Row r = new BareClientsBench(settings).run(name, address);
            String problems = "";
            for (ForkedSubscriber.Result res : List.of(r.flood(), r.paced())) {
                if (!res.complete() || res.duplicates() > 0 || res.outOfOrder() > 0) {
                    problems += String.format("%,d received, complete %s, %d duplicates, %d out of order; ",
                            res.received(), res.complete(), res.duplicates(), res.outOfOrder());
                }
            }
            lines.add(new Line("bare MQTT clients, QoS 1, " + name, r.messagesPerSecond(), r.paced().latency(),
                    problems));
        }
        if (settings.parts().contains("nodes") && nodes) {
            NodeToNodeBench.Row r = new NodeToNodeBench(settings).acrossNodes(name, address);
            lines.add(new Line(r.what(), r.eventsPerSecond(), r.paced(), r.problems()));
        }
        if (install) {
            results.installs().add(new RemoteInstallBench(settings).acrossNodes(name, address));
        }
    }
}
