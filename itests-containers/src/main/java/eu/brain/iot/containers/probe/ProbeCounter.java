package eu.brain.iot.containers.probe;

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
 * numbers, duplicates, and events out of order (a number lower than one taken before). Each event is appended to the
 * configured file before {@code notify()} returns, and the file is read back at start, so the counts cover the
 * node's restarts. Every 200 ms, when something changed, it prints per run:
 * {@code probe counter: run=R received=N distinct=D duplicates=U outOfOrder=O last=S}.
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
        System.out.println("probe counter: ready (" + file + ")");
        reporter.scheduleWithFixedDelay(this::report, REPORT_MS, REPORT_MS, TimeUnit.MILLISECONDS);
    }

    @Override
    public synchronized void notify(ProbeEvent event) {
        runs.computeIfAbsent(event.run, r -> new RunCounts()).take(event.seq);
        try {
            out.write(event.run + " " + event.seq + "\n");
            out.flush(); // to the operating system: kept when the process is killed
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        changed = true;
    }

    private synchronized void report() {
        if (!changed) {
            return;
        }
        changed = false;
        runs.forEach((run, c) -> System.out.println("probe counter: run=" + run + " received=" + c.received
                + " distinct=" + c.seen.cardinality() + " duplicates=" + c.duplicates + " outOfOrder=" + c.outOfOrder
                + " last=" + c.last));
    }

    @Deactivate
    synchronized void stop() throws IOException {
        reporter.shutdownNow();
        out.close();
    }
}
