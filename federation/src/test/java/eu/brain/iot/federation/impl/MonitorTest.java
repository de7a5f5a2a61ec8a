package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;

import eu.brain.iot.federation.impl.FabricNode.NodeView;
import eu.brain.iot.federation.monitoring.api.FabricStatus;
import eu.brain.iot.federation.monitoring.api.RemoteNodeStatus;

/**
 * The fabric node's views as the monitoring API's DTOs: this node apart from the others, each counter in its field,
 * the event types of every interest entry once and sorted, and when each node was first seen in its status.
 */
class MonitorTest {

    private static final String SELF = "node-a";
    private static final String FABRIC = "warehouse";
    private static final String BROKER = "tcp://127.0.0.1:18830";
    private static final NodeStats.Snapshot NOTHING = new NodeStats().snapshot();

    private final AtomicLong clock = new AtomicLong(1_000);
    private final Monitor monitor = new Monitor(clock::get);

    private static NodeView self(String status) {
        return new NodeView(SELF, status, List.of(new InterestEntry(List.of("x.Docked"), null)), NOTHING);
    }

    @Test
    void eachViewBecomesADtoWithItsCountersAndEventTypes() {
        NodeStats.Snapshot stats = new NodeStats.Snapshot(17, 3, 12, 9, 2, 5, 1, 1, 2, 1, 4);
        NodeView b = new NodeView("node-b", "online", List.of(
                new InterestEntry(List.of("x.Moved", "x.Base"), "(robot=r1)"),
                new InterestEntry(List.of("x.Moved"), null)), stats);
        NodeView c = new NodeView("node-c", "unknown", List.of(), NOTHING);

        FabricStatus s = monitor.read(SELF, FABRIC, BROKER, FabricStatus.ONLINE, null,
                List.of(c, self("online (this node)"), b), 2);

        assertThat(s.node).isEqualTo(SELF);
        assertThat(s.fabric).isEqualTo(FABRIC);
        assertThat(s.brokerUri).isEqualTo(BROKER);
        assertThat(s.state).isEqualTo(FabricStatus.ONLINE);
        assertThat(s.problem).isNull();
        assertThat(s.interestEntries).isEqualTo(1);
        assertThat(s.eventTypes).containsExactly("x.Docked");
        assertThat(s.installedBehaviours).isEqualTo(2);
        assertThat(s.remotes).extracting(r -> r.name).as("the others, sorted, this node apart")
                .containsExactly("node-b", "node-c");

        RemoteNodeStatus rb = s.remotes.get(0);
        assertThat(rb.status).isEqualTo(RemoteNodeStatus.ONLINE);
        assertThat(rb.interestEntries).isEqualTo(2);
        assertThat(rb.eventTypes).as("each type once, sorted").containsExactly("x.Base", "x.Moved");
        assertThat(List.of(rb.sent, rb.resent, rb.acknowledged, rb.received, rb.duplicates, rb.refused, rb.backlog))
                .containsExactly(17L, 3L, 12L, 9L, 2L, 5L, 4L);
        assertThat(rb.installedBehaviours).as("not known for another node").isNull();
        assertThat(s.remotes.get(1).status).isEqualTo(RemoteNodeStatus.UNKNOWN);
    }

    @Test
    void sinceIsWhenTheStatusWasFirstReadAndMovesOnlyWhenItChanges() {
        NodeView bOnline = new NodeView("node-b", "online", List.of(), NOTHING);
        NodeView bOffline = new NodeView("node-b", "offline", List.of(), NOTHING);

        FabricStatus first = monitor.read(SELF, FABRIC, BROKER, FabricStatus.JOINING, null,
                List.of(self("joining (this node)"), bOnline), null);
        assertThat(first.since).isEqualTo(1_000);
        assertThat(first.remotes.get(0).since).isEqualTo(1_000);
        assertThat(first.installedBehaviours).as("no installer").isNull();

        clock.set(2_000);
        FabricStatus joined = monitor.read(SELF, FABRIC, BROKER, FabricStatus.ONLINE, null,
                List.of(self("online (this node)"), bOnline), null);
        assertThat(joined.since).as("this node's state changed").isEqualTo(2_000);
        assertThat(joined.remotes.get(0).since).as("node-b's did not").isEqualTo(1_000);

        clock.set(3_000);
        FabricStatus gone = monitor.read(SELF, FABRIC, BROKER, FabricStatus.ONLINE, null,
                List.of(self("online (this node)"), bOffline), null);
        assertThat(gone.since).isEqualTo(2_000);
        assertThat(gone.remotes.get(0).status).isEqualTo(RemoteNodeStatus.OFFLINE);
        assertThat(gone.remotes.get(0).since).isEqualTo(3_000);
    }

    @Test
    void aNodeThatDoesNotJoinSaysWhyAndListsNoOne() {
        FabricStatus s = monitor.read(SELF, FABRIC, BROKER, FabricStatus.NOT_JOINED, "the fabric key file does not "
                + "exist", List.of(), null);

        assertThat(s.state).isEqualTo(FabricStatus.NOT_JOINED);
        assertThat(s.problem).contains("key file");
        assertThat(s.remotes).isEmpty();
        assertThat(s.eventTypes).isEmpty();
    }
}
