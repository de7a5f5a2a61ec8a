package eu.brain.iot.edge.impl;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The edges of the poll benchmark: one edge polling the whole fleet, or N edges each polling its share {@code K/N}
 * (robot number modulo N; the doors on node 1), as the edges of N fabric nodes sharing one fleet do, with the
 * share held for the whole run (no lease: polling only). The edges run in this JVM, each with threads of its own
 * ({@code edge-fleet-<node>}, {@code edge-http-<node>-...}), so that each node's edge CPU is its threads' CPU.
 *
 * <p>Threads: used by the benchmark's main thread only.
 */
final class SharedFleetEdges implements AutoCloseable {
    /** One node's edge. */
    record Node(String name, Edge edge) {
    }

    private final List<Node> nodes;

    private SharedFleetEdges(List<Node> nodes) {
        this.nodes = nodes;
    }

    /**
     * @param settings the edges' settings (their share is set here)
     * @param count    1: one edge owns every device; N: node K of N owns share {@code K/N}
     */
    static SharedFleetEdges start(FleetSettings settings, int count, EventSink sink) {
        List<Node> nodes = new ArrayList<>();
        if (count == 1) {
            nodes.add(new Node(EdgeNode.DEFAULT_NAME, new Edge(settings, sink, EdgeLog.stderr())));
        } else {
            for (int k = 1; k <= count; k++) {
                String name = "node" + k;
                FleetSettings share = settings.withShare(Share.parse(k + "/" + count, 1));
                nodes.add(new Node(name, new Edge(share, name, sink, EdgeLog.stderr())));
            }
        }
        return new SharedFleetEdges(List.copyOf(nodes));
    }

    List<Node> nodes() {
        return nodes;
    }

    /** Waits until the edges answered at least {@code robots} polls between them (every robot once, about). */
    void awaitFirstRound(int robots) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (merged().answered() < robots) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("the edges did not get " + robots + " answers within 120 s: "
                        + merged());
            }
            TimeUnit.MILLISECONDS.sleep(100);
        }
    }

    /** Devices the edges know of (each edge its own share's). */
    int devices() {
        return nodes.stream().mapToInt(n -> n.edge().providers().size()).sum();
    }

    void resetPollStats() {
        nodes.forEach(n -> n.edge().resetPollStats());
    }

    /**
     * Every edge's counts summed; the deviations are the worst edge's (percentiles do not add up), the window the
     * longest.
     */
    PollStats.Snapshot merged() {
        long sent = 0;
        long answered = 0;
        long failed = 0;
        long skipped = 0;
        long onTime = 0;
        long late = 0;
        double seconds = 0;
        double p50 = 0;
        double p99 = 0;
        for (Node n : nodes) {
            PollStats.Snapshot s = n.edge().pollStats();
            sent += s.sent();
            answered += s.answered();
            failed += s.failed();
            skipped += s.skipped();
            onTime += s.onTime();
            late += s.late();
            seconds = Math.max(seconds, s.seconds());
            p50 = Math.max(p50, s.deviationP50Millis());
            p99 = Math.max(p99, s.deviationP99Millis());
        }
        return new PollStats.Snapshot(sent, answered, failed, skipped, onTime, late, seconds, p50, p99);
    }

    /** CPU time of each node's edge threads (fleet thread and HTTP threads), in the order of {@link #nodes()}. */
    long[] threadCpuNanos() {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long[] cpu = new long[nodes.size()];
        for (ThreadInfo t : threads.getThreadInfo(threads.getAllThreadIds())) {
            if (t == null) {
                continue;
            }
            long nanos = threads.getThreadCpuTime(t.getThreadId());
            for (int i = 0; i < nodes.size() && nanos >= 0; i++) {
                String node = nodes.get(i).name();
                String name = t.getThreadName();
                if (name.equals("edge-fleet-" + node) || name.startsWith("edge-http-" + node + "-")) {
                    cpu[i] += nanos;
                }
            }
        }
        return cpu;
    }

    @Override
    public void close() {
        nodes.forEach(n -> n.edge().close());
    }
}
