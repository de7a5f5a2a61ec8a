package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.stream.LongStream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.federation.impl.Events.Moved;
import eu.brain.iot.federation.impl.Events.Recorder;

/**
 * The faults beside the broker restart and the killed node ({@link FabricTest}): a partition between a node and the
 * broker, healed; a remote behaviour that takes its time. Real brokers, real nodes in this JVM, as in FabricTest.
 */
class FabricFaultsTest extends FabricTestBase {

    static final Duration DEADLINE = Duration.ofSeconds(60);
    static final String MOVED = Moved.class.getName();

    @Override
    String logPrefix() {
        return "fabric-faults";
    }

    /** How long the nodes of these tests keep the events of a node that went offline before they give them up. */
    static final long GIVE_UP_MILLIS = 3_000;

    private TestNode node(String name, String brokerUri) throws Exception {
        TestNode n = new TestNode(name, Settings.of(brokerUri, "test", name, key, tmp.resolve("state-" + name))
                .withResendTimeout(1000).withKeepAlive(2).withOfflineGiveUp(GIVE_UP_MILLIS));
        nodes.add(n);
        n.start();
        return n;
    }

    /**
     * The publishing node loses the broker (every connection through the relay closed, new ones refused) while its
     * behaviours publish; once the way is back, what it published meanwhile reaches the other node, once each, in
     * order, and the node is seen online again.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aNodeCutOffFromTheBrokerLosesNothingOnceTheWayIsBack(Broker.Kind kind) throws Exception {
        startBroker(kind);
        try (TcpRelay relay = new TcpRelay(broker.port)) {
            TestNode a = node("a", relay.uri());
            TestNode b = node("b", broker.uri());
            Recorder r = new Recorder();
            b.addBehaviour(r, null, MOVED);
            FabricTest.awaitInterest(a, b, 1);
            int before = 100;
            int during = 400;
            for (int i = 1; i <= before; i++) {
                a.bus.deliver(new Moved("r1", i));
            }

            relay.cut();
            await("a offline at b (its Last Will)").atMost(DEADLINE).until(() -> b.statusOf("a").equals("offline"));
            for (int i = before + 1; i <= before + during; i++) {
                a.bus.deliver(new Moved("r1", i)); // kept on a: b is online as far as a knows
            }
            relay.heal();

            int total = before + during;
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(r.got.size() + " received, backlog "
                    + a.statsOf("b").backlog() + ", a " + b.statusOf("a") + " at b")
                    .isEqualTo(total + " received, backlog 0, a online at b"));
            assertThat(r.seqs()).as("every event once, in publish order").isEqualTo(range(total));
            assertThat(a.bus.statistics(MOVED).unhandled).isZero();
        }
    }

    /**
     * One node's behaviour does not return from {@code notify} for a while: the other node and the publisher's own
     * behaviours get every event meanwhile, and the slow one gets them all afterwards, in order.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aSlowRemoteBehaviourHoldsUpNobodyElse(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a", broker.uri());
        TestNode b = node("b", broker.uri());
        TestNode c = node("c", broker.uri());
        Slow slow = new Slow();
        Recorder atC = new Recorder();
        Recorder local = new Recorder();
        b.addBehaviour(slow, null, MOVED);
        c.addBehaviour(atC, null, MOVED);
        a.addBehaviour(local, null, MOVED);
        FabricTest.awaitInterest(a, b, 1);
        FabricTest.awaitInterest(a, c, 1);

        int total = 300;
        for (int i = 1; i <= total; i++) {
            a.bus.deliver(new Moved("r1", i));
        }
        await("c and a's own behaviour served while b's is stuck").atMost(DEADLINE)
                .until(() -> atC.got.size() == total && local.got.size() == total);
        assertThat(slow.got).as("b's behaviour is still in its first notify").hasSizeLessThanOrEqualTo(1);
        assertThat(atC.seqs()).isEqualTo(range(total));

        slow.release.countDown();
        await().atMost(DEADLINE).until(() -> slow.got.size() == total && a.statsOf("b").backlog() == 0);
        assertThat(slow.got).isEqualTo(range(total));
        assertThat(a.bus.statistics(MOVED).unhandled).isZero();
    }

    /**
     * A node dies for good with events for it not acknowledged (its behaviour never returned): once it has been
     * offline for the give-up time, they reach the behaviour that came since on another node, once each, in order;
     * the publisher's own behaviour, which had them already, gets none again.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void theEventsKeptForANodeGoneForGoodReachTheBehaviourThatCameSince(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a", broker.uri());
        TestNode b = node("b", broker.uri());
        Slow stuck = new Slow(); // never released: b acknowledges nothing
        Recorder atA = new Recorder();
        b.addBehaviour(stuck, null, MOVED);
        a.addBehaviour(atA, null, MOVED);
        FabricTest.awaitInterest(a, b, 1);
        int total = 50;
        for (int i = 1; i <= total; i++) {
            a.bus.deliver(new Moved("r1", i));
        }
        await("kept for b").atMost(DEADLINE).until(() -> atA.got.size() == total
                && a.statsOf("b").backlog() == total);
        long published = System.currentTimeMillis();
        await("the clock moves on").atMost(DEADLINE).until(() -> System.currentTimeMillis() > published);
        TestNode c = node("c", broker.uri());
        Recorder atC = new Recorder();
        c.addBehaviour(atC, null, MOVED); // came after the events: it never had them
        FabricTest.awaitInterest(a, c, 1);

        b.crash();
        await("b offline at a").atMost(DEADLINE).until(() -> a.statusOf("b").equals("offline"));
        await("given up, then taken by c").atMost(DEADLINE).until(() -> atC.got.size() == total);
        assertThat(atC.seqs()).as("every event once, in publish order").isEqualTo(range(total));
        assertThat(a.statsOf("b").backlog()).isZero();
        assertThat(atA.got).as("none again to the behaviour that had them").hasSize(total);
        assertThat(a.log).anyMatch(l -> l.contains("node b stayed offline for " + GIVE_UP_MILLIS + " ms: the " + total
                + " event(s) kept for it are published again"));
    }

    /**
     * A node killed with events sent to its broker session and not acknowledged, and started again once they were
     * given up (and taken by a behaviour on another node): it connects with a clean session, so the copies its old
     * session held never reach it; what is published after its return does.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aNodeBackAfterItsEventsWereGivenUpGetsNoneOfThemFromItsOldSession(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a", broker.uri());
        TestNode b = node("b", broker.uri());
        Recorder atB = new Recorder();
        b.addBehaviour(atB, null, MOVED);
        FabricTest.awaitInterest(a, b, 1);
        atB.dieWith(b); // like kill -9: no goodbye; a sends on to b's session until the broker says b is gone
        nodes.remove(b);
        int total = 50;
        for (int i = 1; i <= total; i++) {
            a.bus.deliver(new Moved("r1", i));
        }
        await("sent to b's session and kept for b").atMost(DEADLINE).until(() -> a.statsOf("b").backlog() == total
                && a.statsOf("b").sent() >= total);
        long published = System.currentTimeMillis();
        await("the clock moves on").atMost(DEADLINE).until(() -> System.currentTimeMillis() > published);
        TestNode c = node("c", broker.uri());
        Recorder atC = new Recorder();
        c.addBehaviour(atC, null, MOVED);
        FabricTest.awaitInterest(a, c, 1);
        await("b offline at a").atMost(DEADLINE).until(() -> a.statusOf("b").equals("offline"));
        await("given up, then taken by c").atMost(DEADLINE).until(() -> atC.got.size() == total);

        TestNode b2 = node("b", broker.uri()); // the same name and state folder
        Recorder atB2 = new Recorder();
        b2.addBehaviour(atB2, null, MOVED);
        await("b back at a").atMost(DEADLINE).until(() -> a.statusOf("b").equals("online"));
        FabricTest.awaitInterest(a, b2, 1);
        a.bus.deliver(new Moved("r1", total + 1));
        await("the event published since reaches b and c").atMost(DEADLINE)
                .until(() -> atB2.got.size() >= 1 && atC.got.size() == total + 1);
        assertThat(atB2.seqs()).as("none of the copies b's old session held").containsExactly((long) total + 1);
        assertThat(atC.seqs()).isEqualTo(range(total + 1));
        assertThat(b2.log).anyMatch(l -> l.contains("it joins with a clean broker session"));
    }

    /** A behaviour whose first {@code notify} does not return until the test releases it. */
    public static final class Slow implements SmartBehaviour<Moved> {
        final List<Long> got = new CopyOnWriteArrayList<>();
        final CountDownLatch release = new CountDownLatch(1);

        @Override
        public void notify(Moved event) {
            got.add(event.seq);
            try {
                release.await(2, TimeUnit.MINUTES);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    static List<Long> range(int total) {
        return LongStream.rangeClosed(1, total).boxed().toList();
    }
}
