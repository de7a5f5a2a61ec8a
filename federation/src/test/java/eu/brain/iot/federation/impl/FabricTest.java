package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

import org.eclipse.paho.mqttv5.client.IMqttToken;
import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttCallback;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.MqttDisconnectResponse;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.eclipse.paho.mqttv5.common.MqttSubscription;
import org.eclipse.paho.mqttv5.common.packet.MqttProperties;
import org.eclipse.paho.mqttv5.common.packet.UserProperty;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import eu.brain.iot.federation.impl.Events.Docked;
import eu.brain.iot.federation.impl.Events.Moved;
import eu.brain.iot.federation.impl.Events.Nobody;
import eu.brain.iot.federation.impl.Events.Recorder;

/**
 * Several fabric nodes in one JVM (each: the real bus core and a real {@link FabricNode}) joined by a real MQTT 5
 * broker started by the test on a free port: Mosquitto (skipped where its binary is missing) and embedded HiveMQ CE.
 */
class FabricTest extends FabricTestBase {

    static final Duration DEADLINE = Duration.ofSeconds(60);
    static final String MOVED = Moved.class.getName();


    @Override
    String logPrefix() {
        return "fabric-test";
    }

    /** A node whose behaviour is registered with its bus before it joins, as a node restarting with it. */
    TestNode node(String name, Recorder behaviour) throws Exception {
        TestNode n = new TestNode(name, settings(name));
        nodes.add(n);
        n.addBehaviour(behaviour, null, MOVED);
        n.start();
        return n;
    }

    /**
     * Wait until {@code on} routes to {@code remote}'s current interest: it sees it online with these entries, and
     * the forwarders are on its bus (added just after the status is noted).
     */
    static void awaitInterest(TestNode on, TestNode remote, int entries) {
        await("interest of " + remote.name + " seen by " + on.name).atMost(DEADLINE).until(() -> on.fabric.nodes()
                .stream().anyMatch(v -> v.node().equals(remote.name) && v.status().equals("online")
                        && v.interest().size() == entries) && on.forwardersTo(remote.name) == entries);
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void eventsGoOnlyToNodesWhoseBehavioursTakeThem(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        TestNode c = node("c");
        Recorder onlyR1 = new Recorder();
        Recorder all = new Recorder();
        Recorder local = new Recorder();
        b.addBehaviour(onlyR1, "(robotId=r1)", MOVED);
        long cId = c.addBehaviour(all, null, MOVED);
        a.addBehaviour(local, null, MOVED);
        awaitInterest(a, b, 1);
        awaitInterest(a, c, 1);

        a.bus.deliver(new Docked("r1", 1, 7)); // a subtype: matched by its supertype, as on the local bus
        a.bus.deliver(new Moved("r2", 2));
        a.bus.deliver(new Nobody()); // no node takes it: it stays on a, counted unhandled there

        await().atMost(DEADLINE).until(() -> onlyR1.got.size() == 1 && all.got.size() == 2 && local.got.size() == 2);
        Moved atB = onlyR1.got.get(0);
        assertThat(atB).isInstanceOf(Docked.class);
        assertThat(((Docked) atB).dock).isEqualTo(7);
        assertThat(atB.robotId).isEqualTo("r1");
        assertThat(atB.timestamp).as("java.time values cross as ISO text and come back typed").isNotNull();
        assertThat(all.seqs()).containsExactly(1L, 2L);
        assertThat(a.statsOf("b").sent()).as("the filtered-out event never left a for b").isEqualTo(1);
        assertThat(a.statsOf("c").sent()).isEqualTo(2);
        assertThat(a.bus.statistics(Nobody.class.getName()).unhandled).isEqualTo(1);
        await().atMost(DEADLINE).until(() -> a.statsOf("b").backlog() == 0 && a.statsOf("c").backlog() == 0);

        // c's behaviour goes away: its interest is withdrawn and a stops sending there
        c.removeBehaviour(cId);
        awaitInterest(a, c, 0);
        a.bus.deliver(new Moved("r3", 3));
        a.bus.deliver(new Moved("r1", 4));
        await().atMost(DEADLINE).until(() -> onlyR1.got.size() == 2 && local.got.size() == 4);
        assertThat(a.statsOf("c").sent()).isEqualTo(2);
        assertThat(all.got).hasSize(2);
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void eventsReachTheBusOnTheThreadThatTookThemFromTheBroker(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        Recorder got = new Recorder();
        b.addBehaviour(got, null, MOVED);
        awaitInterest(a, b, 1);

        for (int i = 1; i <= 20; i++) {
            a.bus.deliver(new Moved("r" + i, i));
        }

        await().atMost(DEADLINE).until(() -> got.got.size() == 20);
        assertThat(got.seqs()).as("every event once, in publish order").isEqualTo(range(1, 20));
        assertThat(b.deliveringThreads).as("no hand-off to the fabric's inbound thread between the broker and the "
                + "bus").isNotEmpty().noneMatch(t -> t.equals("brain-iot-fabric-in"));
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void exactlyOnceInOrderAcrossABrokerRestart(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        Recorder r = new Recorder();
        b.addBehaviour(r, null, MOVED);
        awaitInterest(a, b, 1);

        int total = 3000;
        Thread publisher = new Thread(() -> {
            for (int i = 1; i <= total; i++) {
                a.bus.deliver(new Moved("r1", i));
                if (i % 100 == 0) {
                    pause(5); // a steady stream, so that the restart falls in the middle of it
                }
            }
        });
        publisher.start();
        await().atMost(DEADLINE).until(() -> r.got.size() >= total / 4);
        broker.restart();
        publisher.join(DEADLINE.toMillis());

        await().atMost(DEADLINE).untilAsserted(() -> assertThat(r.got.size() + " received, backlog "
                + a.statsOf("b").backlog() + ", b " + a.statusOf("b") + " at a")
                .isEqualTo(total + " received, backlog 0, b online at a"));
        assertThat(r.seqs()).as("every event once, in publish order").isEqualTo(range(1, total));
        assertThat(a.bus.statistics(MOVED).unhandled).isZero();
        NodeStats.Snapshot s = a.statsOf("b");
        assertThat(s.sent() - s.resent()).as("sent (resends included) less resent: " + s).isEqualTo(s.acked())
                .isEqualTo(total);
    }

    /**
     * A broker that shuts down publishes the Last Will of every client it holds (Mosquitto does), then drops them
     * all: a sees b's will just before it loses the broker itself. The will must not take b's forwarders: the events
     * published until the broker is back would find no consumer on a. The will is sent here as the broker would,
     * signed, about b's connection, right before the restart.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aLastWillPublishedByABrokerShuttingDownIsNotBelieved(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        Recorder r = new Recorder();
        b.addBehaviour(r, null, MOVED);
        awaitInterest(a, b, 1);

        String topic = new Topics("test").status("b");
        byte[] will = new Wire().status(new Wire.Status("b", Wire.Status.OFFLINE, System.currentTimeMillis(),
                System.currentTimeMillis()));
        MqttAsyncClient broker0 = new MqttAsyncClient(broker.uri(), "shutting-down", new MemoryPersistence());
        broker0.connect(new MqttConnectionOptions()).waitForCompletion(15_000);
        AtomicBoolean dispatched = new AtomicBoolean();
        broker0.setCallback(new MqttCallback() {
            @Override
            public void messageArrived(String t, MqttMessage m) {
                dispatched.set(true);
            }

            @Override
            public void disconnected(MqttDisconnectResponse response) {
            }

            @Override
            public void mqttErrorOccurred(MqttException e) {
            }

            @Override
            public void deliveryComplete(IMqttToken token) {
            }

            @Override
            public void connectComplete(boolean reconnect, String uri) {
            }

            @Override
            public void authPacketArrived(int reasonCode, MqttProperties properties) {
            }
        });
        broker0.subscribe(new MqttSubscription(topic, 1)).waitForCompletion(15_000);
        MqttProperties props = new MqttProperties();
        props.setUserProperties(List.of(new UserProperty(MqttLink.SIG, FabricKey.read(key).sign(topic, will))));
        broker0.publish(topic, new MqttMessage(will, 1, false, props)).waitForCompletion(15_000);
        // the broker dispatched it to its subscribers, a among them: a reads it before the broker's goodbye
        await("the will dispatched").atMost(DEADLINE).untilTrue(dispatched);
        broker0.disconnect().waitForCompletion(15_000);
        broker0.close();
        broker.restart();
        int total = 200;
        for (int i = 1; i <= total; i++) {
            a.bus.deliver(new Moved("r1", i)); // while a reconnects: kept for b, not unhandled
        }

        await().atMost(DEADLINE).untilAsserted(() -> assertThat(r.got.size() + " received, backlog "
                + a.statsOf("b").backlog() + ", b " + a.statusOf("b") + " at a")
                .isEqualTo(total + " received, backlog 0, b online at a"));
        assertThat(r.seqs()).isEqualTo(range(1, total));
        assertThat(a.bus.statistics(MOVED).unhandled).isZero();
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aReceiverCrashedAndRestartedMissesNothing(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        Recorder r = new Recorder();
        b.addBehaviour(r, null, MOVED);
        awaitInterest(a, b, 1);

        int total = 3000;
        AtomicLong published = new AtomicLong();
        AtomicBoolean stop = new AtomicBoolean();
        Thread publisher = new Thread(() -> {
            for (int i = 1; i <= total && !stop.get(); i++) {
                a.bus.deliver(new Moved("r1", i));
                published.set(i);
                if (i % 50 == 0) {
                    pause(5);
                }
            }
        });
        publisher.start();
        await().atMost(DEADLINE).until(() -> r.got.size() >= total / 5);
        r.dieWith(b); // like kill -9: no behaviour runs any more, no goodbye; the broker sends b's Last Will
        nodes.remove(b);
        await("b offline at a").atMost(DEADLINE).until(() -> a.statusOf("b").equals("offline"));
        Recorder r2 = new Recorder();
        TestNode b2 = node("b", r2); // the same name and state folder
        publisher.join(DEADLINE.toMillis());

        long unhandledAtA = a.bus.statistics(MOVED).unhandled; // published while b had no interest
        List<Long> seqs = new ArrayList<>();
        String[] report = { "" };
        try {
            await().atMost(DEADLINE).conditionEvaluationListener(c -> report[0] = "received " + seqs.size()
                    + ", unhandled at a " + a.bus.statistics(MOVED).unhandled
                    + ", at b " + b2.bus.statistics(MOVED).unhandled
                    + ", backlog a->b " + a.statsOf("b") + ", b<-a " + b2.statsOf("a")).until(() -> {
                seqs.clear();
                seqs.addAll(r.seqs());
                seqs.addAll(r2.seqs());
                return new HashSet<>(seqs).size() + a.bus.statistics(MOVED).unhandled >= total
                        && a.statsOf("b").backlog() == 0;
            });
        } catch (org.awaitility.core.ConditionTimeoutException e) {
            throw new AssertionError("not all accounted for: " + report[0], e);
        }
        Set<Long> distinct = new HashSet<>(seqs);
        assertThat(distinct.size() + a.bus.statistics(MOVED).unhandled).as("none lost").isEqualTo(total);
        assertThat(seqs.size() - distinct.size()).as("at most the event caught inside notify() comes twice")
                .isLessThanOrEqualTo(1);
        assertThat(isAscending(seqs)).as("publish order: " + seqs).isTrue();
        assertThat(r2.got).as("received after the restart").isNotEmpty();
        assertThat(unhandledAtA).as("events published while b had no interest stay on a (its BMS decides)")
                .isEqualTo(a.bus.statistics(MOVED).unhandled);
    }

    /**
     * A receiving node is killed with events on their way to it, and started again without its behaviour, which
     * comes a little later (as one restored from the installer's journal, or installed from the configuration folder):
     * the events sent again before it is back wait for it on that node, none counted unhandled there.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void eventsReachingARestartedNodeBeforeItsBehaviourWaitForIt(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        Recorder r = new Recorder();
        b.addBehaviour(r, null, MOVED);
        awaitInterest(a, b, 1);
        r.dieWith(b);
        nodes.remove(b);
        int total = 200;
        for (int i = 1; i <= total; i++) {
            a.bus.deliver(new Moved("r1", i)); // a has not seen b go: kept for it
        }
        await("all kept for b").atMost(DEADLINE).until(() -> a.statsOf("b").backlog() == total);

        TestNode b2 = node("b"); // the same name and state folder, its behaviour not back yet
        await("sent again to b").atMost(DEADLINE).until(() -> a.statsOf("b").resent() >= total);
        Recorder r2 = new Recorder();
        b2.addBehaviour(r2, null, MOVED);

        await().atMost(DEADLINE).untilAsserted(() -> assertThat(r2.got.size() + " received, backlog "
                + a.statsOf("b").backlog()).isEqualTo(total + " received, backlog 0"));
        assertThat(r2.seqs()).isEqualTo(range(1, total));
        assertThat(b2.bus.statistics(MOVED).unhandled).as("none unhandled on the restarted node").isZero();
    }

    /**
     * On a node started again, an event kept for a behaviour it no longer runs waits (for the rest of
     * {@link Inbox#STARTING_NANOS}, in case that behaviour is still coming up) without holding up its publisher's
     * events of other types, which its behaviours take at once.
     */
    @ParameterizedTest
    @EnumSource(value = Broker.Kind.class, names = "HIVEMQ") // the inbox's rule, whichever broker carries it
    void anEventNoBehaviourTakesOnARestartedNodeHoldsUpNoEventOfAnotherType(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        Recorder r = new Recorder();
        b.addBehaviour(r, null, MOVED);
        b.addBehaviour((eu.brain.iot.eventing.api.SmartBehaviour<Nobody>) e -> { }, null, Nobody.class.getName());
        awaitInterest(a, b, 2);
        r.dieWith(b);
        nodes.remove(b);
        a.bus.deliver(new Nobody()); // for a behaviour b does not run after its restart
        // kept before the Moved events (each interest entry has a forwarder of its own: no order between them)
        await("kept for b first").atMost(DEADLINE).until(() -> a.statsOf("b").backlog() == 1);
        int total = 20;
        for (int i = 1; i <= total; i++) {
            a.bus.deliver(new Moved("r1", i));
        }
        await("all kept for b").atMost(DEADLINE).until(() -> a.statsOf("b").backlog() == total + 1);

        Recorder r2 = new Recorder();
        TestNode b2 = node("b", r2); // the same name and state folder; Moved events only
        // held up behind the first event, they would come once the 10 s are over
        await("not held up behind the event nobody takes").atMost(Duration.ofNanos(Inbox.STARTING_NANOS / 2))
                .until(() -> r2.got.size() == total);
        assertThat(r2.seqs()).isEqualTo(range(1, total));
        assertThat(b2.bus.statistics(Nobody.class.getName()).unhandled).as("still waiting, not lost").isZero();
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aNodeThatDiesLosesItsInterestByItsLastWill(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a");
        TestNode b = node("b");
        Recorder r = new Recorder();
        b.addBehaviour(r, null, MOVED);
        awaitInterest(a, b, 1);
        a.bus.deliver(new Moved("r1", 1));
        await().atMost(DEADLINE).until(() -> r.got.size() == 1);

        long died = System.nanoTime();
        b.fabric.crash();
        await().atMost(DEADLINE).until(() -> a.statusOf("b").equals("offline"));
        long millis = (System.nanoTime() - died) / 1_000_000;
        assertThat(millis).as("at most 1.5 keep-alive intervals").isLessThanOrEqualTo(3_000);

        a.bus.deliver(new Moved("r1", 2));
        assertThat(a.bus.statistics(MOVED).unhandled).as("no forwarder for a dead node").isEqualTo(1);
        assertThat(a.statsOf("b").sent()).isEqualTo(1);
    }

    static void pause(long millis) {
        try {
            Thread.sleep(millis); // pacing a publisher, not synchronisation
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    static List<Long> range(long from, long to) {
        List<Long> l = new ArrayList<>();
        for (long i = from; i <= to; i++) {
            l.add(i);
        }
        return l;
    }

    static boolean isAscending(List<Long> seqs) {
        for (int i = 1; i < seqs.size(); i++) {
            if (seqs.get(i) < seqs.get(i - 1)) {
                return false;
            }
        }
        return true;
    }
}
