package eu.brain.iot.scenario;

import java.io.PrintStream;
import java.util.Locale;
import java.util.TreeMap;

/** Prints the end of a run: the figures, each check with PASS or FAIL, and the verdict line. Stateless. */
final class Summary {
    private Summary() {
    }

    /** Details longer than this are cut in the terminal (60 carts missing); the report keeps them whole. */
    static final int DETAIL_CHARS = 600;

    static String shorten(String detail) {
        if (detail.length() <= DETAIL_CHARS) {
            return detail;
        }
        int cut = detail.lastIndexOf(", ", DETAIL_CHARS);
        return detail.substring(0, cut > 0 ? cut : DETAIL_CHARS) + ", ... (the whole list is in the report)";
    }

    /**
     * One node of several: {@code node2 killed at 20.0 s: owns robot2; behaviours robot; sent node1 120, node3 4;
     * received node1 80; CPU 12.3 s (41% of one core)}.
     */
    static String nodeLine(NodeReport n) {
        StringBuilder line = new StringBuilder(n.name());
        if (n.killedAtWarehouseMs() != null) {
            line.append(" killed at ").append(WarehouseTime.format(n.killedAtWarehouseMs()));
        }
        if (n.restartedAtWarehouseMs() != null) {
            line.append(", started again at ").append(WarehouseTime.format(n.restartedAtWarehouseMs()));
        }
        line.append(": owns ").append(n.devicesOwned() == null ? "?" : n.devicesOwned().isEmpty() ? "nothing"
                : String.join(", ", n.devicesOwned()));
        line.append("; behaviours ").append(n.behavioursInstalled() == null ? "?"
                : n.behavioursInstalled().isEmpty() ? "none" : String.join(", ", n.behavioursInstalled().stream()
                        .map(b -> b.startsWith(Bundles.BEHAVIOUR_PREFIX) ? b.substring(Bundles.BEHAVIOUR_PREFIX
                                .length()) : b).toList()));
        line.append("; sent ").append(counts(n.eventsSentTo()));
        line.append("; received ").append(counts(n.eventsReceivedFrom()));
        line.append(n.cpuMs() == null ? "; CPU ?" : String.format(Locale.ROOT, "; CPU %.1f s (%.0f%% of one core)",
                n.cpuMs() / 1000.0, n.cpuPercentOfOneCore() == null ? 0.0 : n.cpuPercentOfOneCore()));
        return line.toString();
    }

    private static String counts(java.util.Map<String, Long> counts) {
        if (counts == null) {
            return "?";
        }
        return counts.isEmpty() ? "none" : String.join(", ", new TreeMap<>(counts).entrySet().stream()
                .map(e -> e.getKey() + " " + e.getValue()).toList());
    }

    static void print(PrintStream out, ReportWriter.Run run) {
        WorldSnapshot start = run.start();
        WorldSnapshot end = run.end();
        TreeMap<Long, Long> waits = Figures.waits(start, end);
        out.println();
        out.printf(Locale.ROOT, "warehouse time %s (wall %.1f s, speed x%s)%n",
                WarehouseTime.format(Figures.elapsedMs(start, end)), run.wallMs() / 1000.0, run.options().speed());
        if (run.deliveredAfterMs() >= 0) {
            out.printf(Locale.ROOT, "every cart delivered after %s of warehouse time: %.0f carts per warehouse hour%n",
                    WarehouseTime.format(run.deliveredAfterMs()),
                    Figures.cartsPerHour(end.cartCount(), run.deliveredAfterMs()));
            int doors = end.doc().path("doors").size();
            out.printf(Locale.ROOT, "bounds: doors (alternating) %.0f, fleet %.0f carts per warehouse hour%n",
                    Figures.doorBoundCartsPerHour(doors, 1, end.stepMillis()),
                    FleetBound.cartsPerHour(start.doc(), end.stepMillis()));
        } else {
            out.printf("carts delivered: %d/%d%n", end.cartsInStorage(), end.cartCount());
        }
        out.printf(Locale.ROOT, "robot in front: %d detections, %d waits ended (median %s, longest %s), "
                        + "%.1f%% of robot time spent waiting on another robot, %d deadlocks%n",
                end.nearMisses() - start.nearMisses(), waits.values().stream().mapToLong(Long::longValue).sum(),
                WarehouseTime.format(Figures.quantile(waits, 0.5) * end.stepMillis()),
                WarehouseTime.format(end.longestWaitMs()), 100 * Figures.waitShare(start, end), end.deadlocks());
        out.printf("door openings %d; commands %d accepted, %d refused; missions %d failed, %d cancelled%n",
                end.doorOpenings(), end.commandsAccepted(), end.commandsRefused(), end.missionsFailed(),
                end.missionsCancelled());
        if (run.bus() != null) {
            out.printf(Locale.ROOT, "bus: %d events (%.0f/s), %d commands published, %d outcomes; node CPU %.1f s "
                            + "(%.0f%% of one core)%n", run.bus().totalPublished(),
                    run.wallMs() <= 0 ? 0.0 : run.bus().totalPublished() * 1000.0 / run.wallMs(),
                    run.bus().commandsPublished(), run.bus().outcomesPublished(), run.nodeCpuMs() / 1000.0,
                    run.wallMs() <= 0 ? 0.0 : 100.0 * run.nodeCpuMs() / run.wallMs());
        }
        for (NodeReport n : run.nodes()) {
            out.println(nodeLine(n));
        }
        for (Verdict.Check c : run.verdict().checks()) {
            out.printf("%s  %s: %s%n", c.passed() ? "PASS" : "FAIL", c.name(), shorten(c.detail()));
        }
        out.println(run.verdict().passed() ? "scenario PASSED" : "scenario FAILED: "
                + run.verdict().failed().size() + " of " + run.verdict().checks().size() + " checks failed");
    }
}
