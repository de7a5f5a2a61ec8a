package eu.brain.iot.benchmarks;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/** Prints the environment and the result table. */
final class Report {

    static final long TARGET_EVENTS_PER_SECOND = 1_000_000;
    static final double TARGET_P99_MICROS = 100;

    private final PrintStream out;

    Report(PrintStream out) {
        this.out = out;
    }

    void environment(Settings settings) {
        Runtime rt = Runtime.getRuntime();
        out.printf(Locale.ROOT, "Machine: %d cores (availableProcessors), %s %s, max heap %d MiB%n",
                rt.availableProcessors(), System.getProperty("os.name"), System.getProperty("os.arch"),
                rt.maxMemory() >> 20);
        out.printf(Locale.ROOT, "Java:    %s %s (%s)%n", System.getProperty("java.vm.name"),
                System.getProperty("java.runtime.version"), System.getProperty("java.vm.vendor"));
        out.println("Run:     " + settings);
        load("at the start");
    }

    /**
     * Print the 1/5/15-minute load averages (Linux): on a shared 2-core machine other work skews every figure, so
     * the report says how busy the machine was.
     */
    void load(String when) {
        try {
            String[] avg = Files.readString(Path.of("/proc/loadavg")).trim().split("\\s+");
            out.printf(Locale.ROOT, "Load average %s: %s %s %s (1, 5, 15 min; %d cores)%n", when, avg[0], avg[1], avg[2],
                    Runtime.getRuntime().availableProcessors());
        } catch (IOException | RuntimeException e) {
            out.println("Load average " + when + ": unknown (" + e.getMessage() + ")");
        }
        out.flush();
    }

    void table(List<ContenderResult> results) {
        out.println();
        out.printf(Locale.ROOT, "%-46s | %14s | %14s | %9s | %9s | %9s | %10s%n", "contender (one publisher thread)",
                "8 cons. ev/s", "1 cons. ev/s", "mean µs", "p50 µs", "p99 µs", "p99.9 µs");
        out.println("-".repeat(46) + "-+-" + "-".repeat(14) + "-+-" + "-".repeat(14) + "-+-" + "-".repeat(9) + "-+-"
                + "-".repeat(9) + "-+-" + "-".repeat(9) + "-+-" + "-".repeat(10));
        for (ContenderResult r : results) {
            if (r.error() != null) {
                out.printf(Locale.ROOT, "%-46s | FAILED: %s%n", r.contender().label(), r.error());
                continue;
            }
            out.printf(Locale.ROOT, "%-46s | %,14.0f | %,14.0f | %9.1f | %9.1f | %9.1f | %10.1f%n",
                    r.contender().label(), r.eight().median(), r.one().median(), r.latency().meanMicros(),
                    r.latency().percentileMicros(50), r.latency().percentileMicros(99),
                    r.latency().percentileMicros(99.9));
        }
        out.println();
        out.println("Throughput: median of the measured rounds, events/s end to end (until every consumer counted "
                + "every event).");
        out.println("Latency: 8 consumers, paced publisher; pooled per-consumer samples of receive minus publish time.");
        out.println();
        for (ContenderResult r : results) {
            if (r.error() == null) {
                out.printf(Locale.ROOT, "%s%n  bundles: %s%n  8 consumers: %s%n  1 consumer:  %s%n"
                        + "  latency: %,d samples at %.0f events/s, max %.1f µs%n",
                        r.contender().label(), r.bundles(), rounds(r.eight()), rounds(r.one()),
                        r.latency().sortedNanos().length, r.latency().achievedRate(), r.latency().maxMicros());
            }
        }
        results.stream().filter(r -> r.contender().key().equals("ours") && r.error() == null).findFirst()
                .ifPresent(this::verdict);
        out.flush();
    }

    private void verdict(ContenderResult ours) {
        double rate = ours.eight().median();
        double p99 = ours.latency().percentileMicros(99);
        out.println();
        out.printf(Locale.ROOT, "Target (our bus, 8 consumers): >= %,d events/s: %s (%,.0f); p99 <= %.0f µs: %s (%.1f)%n",
                TARGET_EVENTS_PER_SECOND, rate >= TARGET_EVENTS_PER_SECOND ? "MET" : "NOT MET", rate,
                TARGET_P99_MICROS, p99 <= TARGET_P99_MICROS ? "MET" : "NOT MET", p99);
    }

    private static String rounds(BusMeasurements.Throughput t) {
        StringBuilder s = new StringBuilder();
        for (double r : t.rounds()) {
            s.append(s.isEmpty() ? "" : ", ").append(String.format(Locale.ROOT, "%,.0f", r));
        }
        String switches = t.cost().voluntarySwitches() < 0 ? "n/a"
                : String.format(Locale.ROOT, "%.2f", t.switchesPerEvent());
        return String.format(Locale.ROOT, "%,d events/round, rounds [%s] ev/s; process CPU %.2f µs/event, "
                + "context switches %s/event", t.events(), s, t.cpuMicrosPerEvent(), switches);
    }
}
