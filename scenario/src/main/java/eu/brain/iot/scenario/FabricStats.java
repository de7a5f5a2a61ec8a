package eu.brain.iot.scenario;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * A node's exchanges with the other nodes of its fabric, read from what the federation's Gogo command
 * {@code fabric:stats} prints: a header naming the columns ({@code NODE SENT RESENT ACKED RECEIVED DUPLICATE REFUSED
 * ...}), then one row per remote node, its name and a count per column. The columns are found by their names in the
 * header, so columns added later do not shift these. Immutable.
 *
 * @param sentTo       events this node published to each other node (those sent again included)
 * @param receivedFrom events from each other node handed to this node's bus
 */
record FabricStats(Map<String, Long> sentTo, Map<String, Long> receivedFrom) {
    static final String SENT = "SENT";
    static final String RECEIVED = "RECEIVED";
    private static final String NODE = "NODE";

    FabricStats {
        sentTo = Collections.unmodifiableMap(new TreeMap<>(sentTo));
        receivedFrom = Collections.unmodifiableMap(new TreeMap<>(receivedFrom));
    }

    /** These figures and another's added up, node by node (the other may be null). */
    FabricStats plus(FabricStats other) {
        if (other == null) {
            return this;
        }
        Map<String, Long> sent = new TreeMap<>(sentTo);
        other.sentTo.forEach((node, n) -> sent.merge(node, n, Long::sum));
        Map<String, Long> received = new TreeMap<>(receivedFrom);
        other.receivedFrom.forEach((node, n) -> received.merge(node, n, Long::sum));
        return new FabricStats(sent, received);
    }

    /**
     * @param lines the command's output
     * @return the counts, or null when the output has no table (the node is not in a fabric: the command says why)
     */
    static FabricStats parse(List<String> lines) {
        List<String> header = null;
        Map<String, Long> sent = new TreeMap<>();
        Map<String, Long> received = new TreeMap<>();
        for (String line : lines) {
            List<String> cells = cells(line);
            if (cells.isEmpty()) {
                continue;
            }
            if (header == null) {
                if (cells.get(0).equals(NODE) && cells.contains(SENT) && cells.contains(RECEIVED)) {
                    header = cells;
                }
                continue;
            }
            if (cells.size() != header.size() || !counts(cells)) {
                continue;
            }
            sent.put(cells.get(0), Long.parseLong(cells.get(header.indexOf(SENT))));
            received.put(cells.get(0), Long.parseLong(cells.get(header.indexOf(RECEIVED))));
        }
        return header == null ? null : new FabricStats(sent, received);
    }

    private static List<String> cells(String line) {
        List<String> cells = new ArrayList<>();
        for (String cell : line.trim().split("\\s+")) {
            if (!cell.isEmpty()) {
                cells.add(cell);
            }
        }
        return cells;
    }

    /** Every cell after the node's name is a count. */
    private static boolean counts(List<String> cells) {
        return cells.stream().skip(1).allMatch(c -> c.chars().allMatch(Character::isDigit));
    }
}
