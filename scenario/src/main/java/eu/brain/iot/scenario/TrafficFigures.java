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
 * The robot behaviour's traffic figures, read from the last {@code traffic:} line it wrote in the node's log (it
 * writes one now and then while its planner drives): go-tos sent, how many were legs of a reserved path, planning
 * time per round, legs cancelled. Stateless.
 */
final class TrafficFigures {
    private static final Pattern LINE = Pattern.compile("traffic: (\\d+) rounds, planning ([0-9.]+) ms per round, "
            + "(\\d+) go-tos sent, (\\d+) along reserved paths, (\\d+) robots held, (\\d+) legs cancelled");

    private TrafficFigures() {
    }

    /** Adds the figures to the report's figures; null values when the log has no such line (no planner drove). */
    static void put(ObjectNode figures, Path nodeLog) {
        Matcher last = null;
        if (nodeLog != null && Files.isRegularFile(nodeLog)) {
            try {
                List<String> lines = Files.readAllLines(nodeLog, StandardCharsets.UTF_8);
                for (String line : lines) {
                    Matcher m = LINE.matcher(line);
                    if (m.find()) {
                        last = m;
                    }
                }
            } catch (IOException | java.io.UncheckedIOException e) {
                last = null;
            }
        }
        if (last == null) {
            figures.putNull("goTosSent");
            figures.putNull("goTosAlongReservedPaths");
            figures.putNull("trafficPlanningMsPerRound");
            figures.putNull("trafficLegsCancelled");
            return;
        }
        figures.put("goTosSent", Long.parseLong(last.group(3)));
        figures.put("goTosAlongReservedPaths", Long.parseLong(last.group(4)));
        figures.put("trafficPlanningMsPerRound", Double.parseDouble(last.group(2)));
        figures.put("trafficLegsCancelled", Long.parseLong(last.group(6)));
    }
}
