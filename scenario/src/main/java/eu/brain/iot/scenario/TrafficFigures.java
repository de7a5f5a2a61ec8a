package eu.brain.iot.scenario;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The robot behaviour's traffic figures, read from the {@code traffic:} lines it writes in its node's log now and then
 * while its planner drives: go-tos sent, how many were legs of a reserved path, planning time per round, legs
 * cancelled. Each instance's counts run from its start (or from when it began to drive the fleet), so each
 * instance's last line counts, and the instances add up: in one log, a line with fewer rounds than the one before
 * starts a new instance (the behaviour was restarted); on a fabric of nodes, each node's logs (every life of it)
 * hold the lines of the instance that drove the fleet while it did. Stateless.
 */
final class TrafficFigures {
    private static final Pattern LINE = Pattern.compile("traffic: (\\d+) rounds, planning ([0-9.]+) ms per round, "
            + "(\\d+) go-tos sent, (\\d+) along reserved paths, (\\d+) robots held, (\\d+) legs cancelled");

    /** One instance's counts, or their sum. */
    private record Counts(long rounds, double planningMs, long goTos, long reserved, long cancelled) {
        static final Counts NONE = new Counts(0, 0, 0, 0, 0);

        static Counts of(Matcher m) {
            long rounds = Long.parseLong(m.group(1));
            return new Counts(rounds, rounds * Double.parseDouble(m.group(2)), Long.parseLong(m.group(3)),
                    Long.parseLong(m.group(4)), Long.parseLong(m.group(6)));
        }

        Counts plus(Counts o) {
            return new Counts(rounds + o.rounds, planningMs + o.planningMs, goTos + o.goTos, reserved + o.reserved,
                    cancelled + o.cancelled);
        }
    }

    private TrafficFigures() {
    }

    /** {@link #put(ObjectNode, List)} with one log. */
    static void put(ObjectNode figures, Path nodeLog) {
        put(figures, nodeLog == null ? List.of() : List.of(nodeLog));
    }

    /**
     * Adds the figures of every instance in these logs to the report's figures; null values when no log has such a
     * line (no planner drove), or none can be read.
     */
    static void put(ObjectNode figures, List<Path> nodeLogs) {
        Counts sum = null;
        for (Path log : nodeLogs) {
            Counts inLog = read(log);
            if (inLog != null) {
                sum = sum == null ? inLog : sum.plus(inLog);
            }
        }
        if (sum == null) {
            figures.putNull("goTosSent");
            figures.putNull("goTosAlongReservedPaths");
            figures.putNull("trafficPlanningMsPerRound");
            figures.putNull("trafficLegsCancelled");
            return;
        }
        figures.put("goTosSent", sum.goTos());
        figures.put("goTosAlongReservedPaths", sum.reserved());
        figures.put("trafficPlanningMsPerRound", sum.rounds() == 0 ? 0
                : Math.round(100 * sum.planningMs() / sum.rounds()) / 100.0);
        figures.put("trafficLegsCancelled", sum.cancelled());
    }

    /** The sum of each instance's last line in this log, or null when it has none or cannot be read. */
    private static Counts read(Path log) {
        if (log == null || !Files.isRegularFile(log)) {
            return null;
        }
        List<String> lines;
        try {
            lines = Files.readAllLines(log, StandardCharsets.UTF_8);
        } catch (IOException | java.io.UncheckedIOException e) {
            return null;
        }
        Counts done = Counts.NONE; // the instances before the current one
        Counts current = null;
        for (String line : lines) {
            Matcher m = LINE.matcher(line);
            if (m.find()) {
                Counts next = Counts.of(m);
                if (current != null && next.rounds() < current.rounds()) {
                    done = done.plus(current);
                }
                current = next;
            }
        }
        return current == null ? null : done.plus(current);
    }
}
