package eu.brain.iot.benchmarks.fabric;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * {@link SubscriberMain} in a JVM of its own, started with this JVM's class path; its output lines are read by a
 * thread of their own into a queue that the benchmark thread takes from with deadlines.
 */
final class ForkedSubscriber implements AutoCloseable {
    /** What the subscriber measured. */
    record Result(long received, boolean complete, long firstMeasuredNanos, long lastNanos, LatencyStats latency,
            long duplicates, long outOfOrder) {
    }

    private final Process process;
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();

    ForkedSubscriber(BrokerAddress broker, String topic, String clientId, int count, int warmup, long timeoutS)
            throws IOException {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        process = new ProcessBuilder(List.of(java.toString(), "-Xms256m", "-Xmx256m", "-cp",
                System.getProperty("java.class.path"), SubscriberMain.class.getName(), broker.uri(), topic, clientId,
                String.valueOf(count), String.valueOf(warmup), String.valueOf(timeoutS)))
                .redirectErrorStream(true).start();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String l = r.readLine(); l != null; l = r.readLine()) {
                    lines.add(l);
                }
            } catch (IOException e) {
                lines.add("error reading the subscriber: " + e);
            }
            lines.add("end");
        }, "subscriber-output");
        reader.setDaemon(true);
        reader.start();
    }

    void awaitReady(long timeoutS) throws IOException, InterruptedException {
        expect("ready", timeoutS);
    }

    Result awaitResult(long timeoutS) throws IOException, InterruptedException {
        String line = expect("result ", timeoutS);
        Map<String, String> f = new HashMap<>();
        for (String pair : line.substring("result ".length()).split(" ")) {
            int eq = pair.indexOf('=');
            f.put(pair.substring(0, eq), pair.substring(eq + 1));
        }
        return new Result(Long.parseLong(f.get("received")), Boolean.parseBoolean(f.get("complete")),
                Long.parseLong(f.get("firstMeasuredNs")), Long.parseLong(f.get("lastNs")),
                new LatencyStats((int) Long.parseLong(f.get("received")), Long.parseLong(f.get("p50Ns")),
                        Long.parseLong(f.get("p99Ns")), Long.parseLong(f.get("maxNs"))),
                Long.parseLong(f.get("duplicates")), Long.parseLong(f.get("outOfOrder")));
    }

    private String expect(String prefix, long timeoutS) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutS);
        StringBuilder other = new StringBuilder();
        while (true) {
            String line = lines.poll(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            if (line == null || line.equals("end")) {
                throw new IOException("the subscriber " + (line == null ? "said nothing within " + timeoutS + " s"
                        : "ended") + " while '" + prefix + "' was expected; its output: " + other);
            }
            if (line.startsWith(prefix)) {
                return line;
            }
            other.append(line).append('\n');
        }
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
        }
    }
}
