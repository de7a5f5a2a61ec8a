package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import eu.brain.iot.federation.impl.Events.Moved;
import eu.brain.iot.federation.impl.Events.Recorder;

/**
 * Retained messages a client without the fabric key publishes on the fabric's topics, and a node with another
 * fabric's key: a forged message on a node's own status or interest is replaced at once by the node's own (nodes that
 * start later see it), a removal of a live node's retained messages changes no other node's routing to it, forged
 * names never enter a node's table, and both sides of a wrong key say so in the log.
 */
class ForgedMessagesTest extends FabricTestBase {

    static final Duration DEADLINE = Duration.ofSeconds(60);
    static final String MOVED = Moved.class.getName();
    static final byte[] GARBAGE = "garbage".getBytes(StandardCharsets.UTF_8);
    /** Retained messages of one node an attacker removes: its status and its interest. */
    static final int REMOVALS = 2;

    Intruder attacker;

    @Override
    String logPrefix() {
        return "forged-messages-test";
    }

    @AfterEach
    void closeAttacker() throws Exception {
        if (attacker != null) {
            attacker.close();
        }
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aForgedRetainedStatusAndInterestOfALiveNodeAreReplacedByItsOwn(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        b.addBehaviour(new Recorder(), null, MOVED);
        FabricTest.awaitInterest(a, b, 1);

        Topics topics = new Topics("test");
        connectAttacker();
        publish(topics.status("b"), GARBAGE, null, true);
        publish(topics.interest("b"), GARBAGE, null, true);
        await("b refuses both").atMost(DEADLINE).until(() -> b.fabric.unverified().unsigned() == 2);

        TestNode c = node("c"); // started after: it finds at the broker what b published again
        FabricTest.awaitInterest(c, b, 1);
        assertThat(b.log).filteredOn(l -> l.startsWith("WARN") && l.contains("on its own retained topic "
                + topics.status("b") + ": it carries no signature")).hasSize(1);
        assertThat(b.log).filteredOn(l -> l.contains("on its own retained topic " + topics.interest("b")))
                .singleElement().asString().contains("this node publishes its own again");
        assertThat(a.statusOf("b")).isEqualTo("online");
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void anUnsignedRemovalOfALiveNodesRetainedMessagesChangesNoOtherNodesRouting(Broker.Kind kind)
            throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        Recorder r = new Recorder();
        TestNode b = node("b");
        b.addBehaviour(r, null, MOVED);
        FabricTest.awaitInterest(a, b, 1);

        Topics topics = new Topics("test");
        connectAttacker();
        publish(topics.interest("b"), new byte[0], null, true); // as mosquitto_pub -r -n would
        publish(topics.status("b"), new byte[0], null, true);
        await("a hears both removals").atMost(DEADLINE)
                .until(() -> a.statsOf("b").unsigned() == REMOVALS || a.forwardersRemovedTo("b") > 0);
        assertThat(a.forwardersRemovedTo("b")).as("a's forwarders to b, all kept").isZero();
        assertThat(a.statsOf("b").unsigned()).as("refused in b's row").isEqualTo(REMOVALS);
        assertThat(a.log).filteredOn(l -> l.startsWith("WARN") && l.contains("claiming to come from node b"))
                .singleElement().asString().contains("it removes the retained message (an empty payload)")
                .contains("(counted in fabric:stats as UNSIGNED, row b)");
        assertThat(a.fabric.unverified().refused()).as("b is a node a knows").isZero();

        a.bus.deliver(new Moved("r1", 1));
        await("a still routes to b").atMost(DEADLINE).until(() -> r.seqs().equals(List.of(1L)));
        assertThat(a.statusOf("b")).isEqualTo("online");
        await("b refuses the removals of its own").atMost(DEADLINE)
                .until(() -> b.fabric.unverified().unsigned() == REMOVALS);
        TestNode c = node("c"); // started after: it finds at the broker what b published again
        FabricTest.awaitInterest(c, b, 1);
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void forgedNamesNeverEnterTheTableOfNodes(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        FabricTest.awaitInterest(a, b, 0);

        Topics topics = new Topics("test");
        connectAttacker();
        publish(topics.status("evil"), GARBAGE, null, true);
        publish(topics.interest("evil"), GARBAGE, null, true);
        publish(topics.status("evil2"), GARBAGE, FabricKey.of(new byte[32]).sign(topics.status("evil2"), GARBAGE),
                true);
        int forged = 3;
        await("refused as unverified").atMost(DEADLINE).until(() -> a.fabric.unverified().refused() == forged
                && b.fabric.unverified().refused() == forged);
        publish(topics.status("evil"), new byte[0], null, true); // the retained messages removed
        publish(topics.interest("evil"), new byte[0], null, true);
        publish(topics.status("evil2"), new byte[0], null, true);
        await("the removals refused as unverified too").atMost(DEADLINE)
                .until(() -> a.fabric.unverified().refused() == 2 * forged
                        && b.fabric.unverified().refused() == 2 * forged);

        TestNode c = node("c"); // started after the forged messages were removed: a fresh view
        FabricTest.awaitInterest(a, c, 0);
        for (TestNode n : List.of(a, b)) {
            assertThat(n.fabric.nodes()).extracting(FabricNode.NodeView::node).as("the table of " + n.name)
                    .containsExactly("a", "b", "c");
            assertThat(n.log).filteredOn(l -> l.contains("claiming to come from node evil2"))
                    .as("its forged status, then its removal").satisfiesExactly(
                            l -> assertThat(l).contains("(counted in fabric:stats as BAD-SIG, row (unverified))"),
                            l -> assertThat(l).contains("it removes the retained message")
                                    .contains("(counted in fabric:stats as UNSIGNED, row (unverified))"));
        }
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aNodeWithAnotherFabricsKeyIsToldOnBothSides(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        FabricTest.awaitInterest(a, b, 0);
        Path otherKey = tmp.resolve("other-fabric.key");
        FabricKey.generate(otherKey);
        TestNode c = new TestNode("c", Settings.of(broker.uri(), "test", "c", otherKey, tmp.resolve("state-c"))
                .withResendTimeout(1000).withKeepAlive(2));
        nodes.add(c);
        c.start();

        await("a refuses c's status and interest").atMost(DEADLINE)
                .until(() -> a.fabric.unverified().badSignature() == 2);
        assertThat(a.log).filteredOn(l -> l.startsWith("WARN") && l.contains("claiming to come from node c"))
                .as("one line for both").singleElement().asString()
                .contains("its signature does not match this node's fabric key")
                .contains("The sending node may use another fabric key: every node of a fabric needs the same key "
                        + "file; federation/README.md (\"Trust\") says how to share it");
        await("c says its key is most likely wrong").atMost(DEADLINE).until(() -> c.log.stream()
                .anyMatch(l -> l.startsWith("WARN") && l.contains("has refused every message of the other nodes "
                        + "(a, b)") && l.contains("this node's key file " + otherKey + " is most likely not")));
        assertThat(c.fabric.nodes()).extracting(FabricNode.NodeView::node).containsExactly("c");
        assertThat(a.fabric.nodes()).extracting(FabricNode.NodeView::node).containsExactly("a", "b");
    }

    private void connectAttacker() throws Exception {
        attacker = new Intruder(broker.uri());
    }

    private void publish(String topic, byte[] payload, String signature, boolean retained) throws Exception {
        attacker.publish(topic, payload, signature, retained);
    }
}
