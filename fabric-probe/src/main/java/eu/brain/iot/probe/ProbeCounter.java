package eu.brain.iot.probe;

import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.api.SmartBehaviour;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.BitSet;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;

/**
 * A behaviour that counts probe events inside {@code notify()}, per run: how many it took, how many distinct
 * numbers, duplicates, and events out of order (a number lower than one taken before). With a file configured, each
 * event is appended to it before {@code notify()} returns, and the file is read back at start, so the counts cover
 * the node's restarts. Every 200 ms, when something changed, it prints per run:
 * {@code probe counter: run=R received=N distinct=D duplicates=U outOfOrder=O last=S}; once a run has been quiet
 * for one such period, its latency over the events taken since this start (receive time minus the event's
 * {@code sentNanos}) and the receive times of its first and last events:
 * {@code probe latency: run=R n=N p50Ns=.. p99Ns=.. maxNs=.. firstNs=.. lastNs=..}.
 *
 * <p>Threads: the bus calls {@code notify} (one call at a time per behaviour, but not always on the same thread)
 * and a reporter thread prints: both hold the monitor of this object for the counts and the file.
 */
@Component(service = SmartBehaviour.class, configurationPid = ProbeCounterConfig.PID,
        configurationPolicy = ConfigurationPolicy.REQUIRE, immediate = true)
@SmartBehaviourDefinition(consumed = ProbeEvent.class, name = "probe counter", author = "BRAIN-IoT fabric tests")
public final class ProbeCounter implements SmartBehaviour<ProbeEvent> {
    private static final long REPORT_MS = 200;

    /** One run's counts. */
    private static final class RunCounts {
        final BitSet seen = new BitSet();
        long received;
        long duplicates;
        long outOfOrder;
        long last;
        long[] latencies = new long[1024];
        int samples;
        long firstNanos;
        long lastNanos;
        boolean latencyShown = true;

        void sample(long receivedNanos, long sentNanos) {
            if (samples == 0) {
                firstNanos = receivedNanos;
            }
            lastNanos = receivedNanos;
            if (samples == latencies.length) {
                latencies = java.util.Arrays.copyOf(latencies, samples * 2);
            }
            latencies[samples++] = receivedNanos - sentNanos;
            latencyShown = false;
        }

        String latencyLine(String run) {
            long[] sorted = java.util.Arrays.copyOf(latencies, samples);
            java.util.Arrays.sort(sorted);
            return "probe latency: run=" + run + " n=" + samples + " p50Ns=" + percentile(sorted, 0.50) + " p99Ns="
                    + percentile(sorted, 0.99) + " maxNs=" + sorted[samples - 1] + " firstNs=" + firstNanos
                    + " lastNs=" + lastNanos;
        }

        private static long percentile(long[] sorted, double q) {
            int i = (int) Math.ceil(q * sorted.length) - 1;
            return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
        }

        void take(long seq) {
            received++;
            if (seen.get((int) seq)) {
                duplicates++;
            } else {
                seen.set((int) seq);
            }
            if (seq < last) {
                outOfOrder++;
            }
            last = Math.max(last, seq);
        }
    }

    private final Map<String, RunCounts> runs = new TreeMap<>();
    private final BufferedWriter out;
    private final ScheduledExecutorService reporter = Executors.newSingleThreadScheduledExecutor(
            r -> new Thread(r, "probe-counter-report"));
    private boolean changed;

    @Activate
    public ProbeCounter(ProbeCounterConfig config) throws IOException {
        if (config.file().isEmpty()) {
            out = null;
        } else {
            Path file = Path.of(config.file());
            Files.createDirectories(file.toAbsolutePath().getParent());
            if (Files.exists(file)) {
                for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
                    String[] f = line.split(" ");
                    if (f.length == 2) {
                        runs.computeIfAbsent(f[0], r -> new RunCounts()).take(Long.parseLong(f[1]));
                    }
                }
                changed = !runs.isEmpty();
            }
            out = Files.newBufferedWriter(file, StandardCharsets.UTF_8, StandardOpenOption.CREATE,
                    StandardOpenOption.APPEND);
        }
        System.out.println("probe counter: ready (" + (out == null ? "counts in memory" : config.file()) + ")");
        reporter.scheduleWithFixedDelay(this::report, REPORT_MS, REPORT_MS, TimeUnit.MILLISECONDS);
    }

    @Override
    public synchronized void notify(ProbeEvent event) {
        long now = System.nanoTime();
        RunCounts counts = runs.computeIfAbsent(event.run, r -> new RunCounts());
        counts.take(event.seq);
        if (event.sentNanos != 0) {
            counts.sample(now, event.sentNanos);
        }
        if (out != null) {
            try {
                out.write(event.run + " " + event.seq + "\n");
                out.flush(); // to the operating system: kept when the process is killed
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        changed = true;
    }

    private synchronized void report() {
        if (changed) {
            changed = false;
            runs.forEach((run, c) -> System.out.println("probe counter: run=" + run + " received=" + c.received
                    + " distinct=" + c.seen.cardinality() + " duplicates=" + c.duplicates + " outOfOrder="
                    + c.outOfOrder + " last=" + c.last));
            return; // the latency waits for a quiet period: sorting the samples while events flow would slow them
        }
        runs.forEach((run, c) -> {
            if (!c.latencyShown && c.samples > 0) {
                c.latencyShown = true;
                System.out.println(c.latencyLine(run));
            }
        });
    }

    @Deactivate
    synchronized void stop() throws IOException {
        reporter.shutdownNow();
        if (out != null) {
            out.close();
        }
    }
}
