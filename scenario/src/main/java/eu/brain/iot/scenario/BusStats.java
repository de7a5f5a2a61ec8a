package eu.brain.iot.scenario;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The node's event bus counters, read from what its Gogo command {@code bus:stats} prints: one row per event type,
 * {@code TYPE PUBLISHED DELIVERED FAILED UNHANDLED DISCARDED HELD}. Immutable.
 *
 * @param published events published per type since the node started
 */
record BusStats(Map<String, Long> published) {
    private static final Pattern ROW = Pattern.compile("^(\\S+)\\s+(\\d+)\\s+(\\d+)\\s+(\\d+)\\s+(\\d+)\\s+(\\d+)\\s+(\\d+)\\s*$");
    /** The edge's commands: what behaviours publish to drive the fleet ({@code eu.brain.iot.edge.api.*Command}). */
    private static final Pattern COMMAND = Pattern.compile("eu\\.brain\\.iot\\.edge\\.api\\.\\w+Command");

    static BusStats parse(List<String> lines) {
        Map<String, Long> published = new LinkedHashMap<>();
        for (String line : lines) {
            Matcher m = ROW.matcher(line);
            if (m.matches()) {
                published.put(m.group(1), Long.parseLong(m.group(2)));
            }
        }
        return new BusStats(Map.copyOf(published));
    }

    /** These counters and another node's, added type by type. */
    BusStats plus(BusStats other) {
        Map<String, Long> sum = new LinkedHashMap<>(published);
        other.published.forEach((type, n) -> sum.merge(type, n, Long::sum));
        return new BusStats(Map.copyOf(sum));
    }

    long totalPublished() {
        return published.values().stream().mapToLong(Long::longValue).sum();
    }

    /** Command events the behaviours published to the edge. */
    long commandsPublished() {
        return published.entrySet().stream().filter(e -> COMMAND.matcher(e.getKey()).matches())
                .mapToLong(Map.Entry::getValue).sum();
    }

    /** The edge's answers to them ({@code CommandOutcome}). */
    long outcomesPublished() {
        return published.getOrDefault("eu.brain.iot.edge.api.CommandOutcome", 0L);
    }

    /** Has every command published an outcome, no more and no fewer? */
    boolean everyCommandAnswered() {
        return commandsPublished() == outcomesPublished();
    }
}
