package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** {@code fabric:stats} output (federation's FabricCommands.stats) read into per-node counts. */
class FabricStatsTest {
    /** As FabricCommands formats it: {@code %-20s %10s %8s %10s %10s %10s %8s %8s %8s %8s %8s}. */
    private static String row(String node, long... n) {
        return String.format("%-20s %10d %8d %10d %10d %10d %8d %8d %8d %8d %8d", node, n[0], n[1], n[2], n[3], n[4],
                n[5], n[6], n[7], n[8], n[9]);
    }

    private static final String HEADER = String.format("%-20s %10s %8s %10s %10s %10s %8s %8s %8s %8s %8s", "NODE",
            "SENT", "RESENT", "ACKED", "RECEIVED", "DUPLICATE", "REFUSED", "UNSIGNED", "BAD-SIG", "REPLAYED",
            "BACKLOG");

    @Test
    void sentAndReceivedArePerRemoteNode() {
        FabricStats stats = FabricStats.parse(List.of(HEADER,
                row("node2", 120, 3, 117, 80, 1, 0, 0, 0, 0, 3),
                row("node3", 4, 0, 4, 0, 0, 0, 0, 0, 0, 0)));
        assertThat(stats.sentTo()).containsExactlyInAnyOrderEntriesOf(Map.of("node2", 120L, "node3", 4L));
        assertThat(stats.receivedFrom()).containsExactlyInAnyOrderEntriesOf(Map.of("node2", 80L, "node3", 0L));
    }

    @Test
    void columnsAreFoundByTheirNamesAndOtherLinesAreSkipped() {
        FabricStats stats = FabricStats.parse(List.of("", "some echo",
                "NODE RECEIVED EXTRA SENT", "a-very-long-node-name-beyond-twenty 5 9 7", "node9 x 1 2", "  "));
        assertThat(stats.sentTo()).containsExactlyEntriesOf(Map.of("a-very-long-node-name-beyond-twenty", 7L));
        assertThat(stats.receivedFrom()).containsExactlyEntriesOf(Map.of("a-very-long-node-name-beyond-twenty", 5L));
    }

    @Test
    void aNodeAloneInItsFabricHasATableWithNoRows() {
        FabricStats stats = FabricStats.parse(List.of(HEADER));
        assertThat(stats.sentTo()).isEmpty();
        assertThat(stats.receivedFrom()).isEmpty();
    }

    @Test
    void aNodeNotInAFabricHasNoTable() {
        assertThat(FabricStats.parse(List.of("This node is not a member of a fabric: configure PID "
                + "eu.brain.iot.federation (broker.uri, fabric.name, key.file; see federation/README.md)."))).isNull();
        assertThat(FabricStats.parse(List.of())).isNull();
    }

    @Test
    void twoLivesOfANodeAddUpNodeByNode() {
        FabricStats first = new FabricStats(java.util.Map.of("node1", 100L), java.util.Map.of("node1", 80L));
        FabricStats second = new FabricStats(java.util.Map.of("node1", 10L, "node3", 5L), java.util.Map.of());
        FabricStats both = first.plus(second);
        assertThat(both.sentTo()).containsExactlyEntriesOf(new java.util.TreeMap<>(java.util.Map.of("node1", 110L,
                "node3", 5L)));
        assertThat(both.receivedFrom()).containsEntry("node1", 80L).hasSize(1);
        assertThat(first.plus(null)).isSameAs(first);
    }
}
