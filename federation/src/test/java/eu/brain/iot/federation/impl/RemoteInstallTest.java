package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.stream.LongStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.osgi.util.promise.Deferred;
import org.osgi.util.promise.Promise;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.federation.impl.Events.Moved;
import eu.brain.iot.federation.impl.Events.Recorder;

/**
 * The BMS's choice of the node that installs a behaviour, through the fabric's installer ({@link FabricInstaller}):
 * several nodes in one JVM (each the real bus core and a real {@link FabricNode}) joined by a real broker started by
 * the test (Mosquitto, skipped where missing, and embedded HiveMQ CE); each node's own installer is a
 * {@link FakeInstaller} whose install registers a behaviour with that node's bus; the BMS of the asking node is the
 * part of it that uses the installer ({@link MiniBms}). Bids, offers, orders and results are the fabric's real,
 * signed messages.
 */
class RemoteInstallTest extends FabricTestBase {

    static final Duration DEADLINE = Duration.ofSeconds(60);
    static final String MOVED = Moved.class.getName();
    static final String RECORDER = "eu.brain.iot.test.recorder";


    @Override
    String logPrefix() {
        return "remote-install";
    }


    /** A started node whose own installer is {@code installer}. */
    TestNode node(String name, FakeInstaller installer) throws Exception {
        TestNode n = new TestNode(name, settings(name));
        nodes.add(n);
        n.start();
        n.fabric.localInstaller(installer);
        return n;
    }

    /** An installer that offers the recorder for {@code Moved} and, asked, registers it with {@code on}'s bus. */
    static FakeInstaller offering(TestNode[] on, Recorder recorder) {
        FakeInstaller f = new FakeInstaller();
        f.offers = Map.of(MOVED, FakeInstaller.candidate(RECORDER, MOVED));
        f.onInstall = r -> {
            on[0].addBehaviour(recorder, null, MOVED);
            return org.osgi.util.promise.Promises.resolved(FakeInstaller.installed(RECORDER));
        };
        return f;
    }

    static void awaitOnline(TestNode on, TestNode... others) {
        for (TestNode other : others) {
            await(other.name + " online for " + on.name).atMost(DEADLINE).until(() -> on.statusOf(other.name)
                    .equals("online"));
        }
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void heldEventsReachTheBehaviourInstalledOnTheNodeThatOffersIt(Broker.Kind kind) throws Exception {
        startBroker(kind);
        Recorder recorder = new Recorder();
        TestNode[] bRef = new TestNode[1];
        FakeInstaller atA = new FakeInstaller(); // a's repositories have nothing for it
        FakeInstaller atB = offering(bRef, recorder);
        FakeInstaller atC = new FakeInstaller();
        TestNode a = node("a", atA);
        bRef[0] = node("b", atB);
        TestNode c = node("c", atC);
        awaitOnline(a, bRef[0], c);
        MiniBms bms = new MiniBms(a.fabric.installer(), MOVED);
        a.bus.policy(bms);

        int held = 300;
        for (int i = 1; i <= held; i++) {
            a.bus.deliver(new Moved("r1", i)); // nobody consumes it: held on a while the fabric chooses
        }
        assertThat(bms.found.get(30, TimeUnit.SECONDS)).extracting(cand -> cand.node).containsOnly("b");
        InstalledBehaviour done = bms.outcome.get(30, TimeUnit.SECONDS);
        assertThat(done.symbolicName).isEqualTo(RECORDER);
        for (int i = held + 1; i <= held + 100; i++) {
            a.bus.deliver(new Moved("r1", i)); // after the install: routed to b at once
        }
        await().atMost(DEADLINE).until(() -> recorder.got.size() >= held + 100);
        await().during(Duration.ofMillis(300)).atMost(DEADLINE).until(() -> recorder.got.size() == held + 100);
        assertThat(recorder.seqs()).as("every held event once, in publish order, then the newer ones")
                .containsExactlyElementsOf(LongStream.rangeClosed(1, held + 100).boxed().toList());
        assertThat(atB.installs).hasSize(1);
        assertThat(atB.installs.get(0).node).as("the installing node's own installer gets a local request").isNull();
        assertThat(atA.installs).isEmpty();
        assertThat(atC.installs).isEmpty();
        assertThat(a.bus.held()).isEmpty();
        assertThat(a.log).anyMatch(l -> l.contains("node b installs " + RECORDER));
    }

    /**
     * Three nodes offer the behaviour with the same load; the held events name a robot that node b's edge owns: b
     * installs it, though a2 has the lower name of the nodes other than a, which asks (the choice when the event names
     * no device).
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void theNodeThatOwnsTheRobotTheEventNamesInstalls(Broker.Kind kind) throws Exception {
        startBroker(kind);
        Recorder onA = new Recorder();
        Recorder onB = new Recorder();
        TestNode[] aRef = new TestNode[1];
        TestNode[] bRef = new TestNode[1];
        FakeInstaller atA = offering(aRef, onA);
        FakeInstaller atB = offering(bRef, onB);
        Recorder onA2 = new Recorder();
        TestNode[] a2Ref = new TestNode[1];
        FakeInstaller atA2 = offering(a2Ref, onA2);
        aRef[0] = node("a", atA);
        bRef[0] = node("b", atB);
        a2Ref[0] = node("a2", atA2);
        TestNode a = aRef[0];
        ((FabricInstaller) bRef[0].fabric.installer()).ownedDevices("robot2"::equals);
        awaitOnline(a, bRef[0], a2Ref[0]);
        assertThat(a.fabric.installer().find(List.of(MOVED)).getValue())
                .as("no device named: not the node that asks, then the lower name").extracting(cand -> cand.node)
                .containsOnly("a2");

        MiniBms bms = new MiniBms(a.fabric.installer(), MOVED); // asks with the first event's fields, from the bus
        a.bus.policy(bms);
        int held = 100;
        for (int i = 1; i <= held; i++) {
            a.bus.deliver(new Moved("robot2", i));
        }
        assertThat(bms.found.get(30, TimeUnit.SECONDS)).extracting(cand -> cand.node).containsOnly("b");
        bms.outcome.get(30, TimeUnit.SECONDS);
        await().atMost(DEADLINE).until(() -> onB.got.size() >= held);
        await().during(Duration.ofMillis(300)).atMost(DEADLINE).until(() -> onB.got.size() == held);
        assertThat(onB.seqs()).containsExactlyElementsOf(LongStream.rangeClosed(1, held).boxed().toList());
        assertThat(atB.installs).hasSize(1);
        assertThat(atA.installs).isEmpty();
        assertThat(atA2.installs).isEmpty();
        assertThat(onA.got).isEmpty();
        assertThat(a.log).anyMatch(l -> l.contains("node b installs " + RECORDER + " for events of " + MOVED
                + " naming [robot2] (owns [robot2], load 0"));
    }

    /**
     * The node that owns the robot the event names answers later than {@code install.bid.ms} (its installer is
     * slow): it is waited for, not passed over for the asking node, whose offer owns nothing.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void theNodeThatOwnsTheNamedRobotIsWaitedForWhenItAnswersLate(Broker.Kind kind) throws Exception {
        startBroker(kind);
        assertThat(choiceWithBAnsweringLate(Map.of("robotId", "robot2"), true)).containsOnly("b");
    }

    /**
     * For an event that names no device, the asking node's own offer alone is not the choice while another node that
     * may offer the behaviour is still to answer: b, answering late, installs it (beside a, which published the event,
     * the behaviour would die with it).
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void anotherNodeThatOffersIsWaitedForWhenItAnswersLateAndTheEventNamesNoDevice(Broker.Kind kind)
            throws Exception {
        startBroker(kind);
        assertThat(choiceWithBAnsweringLate(Map.of(), false)).containsOnly("b");
    }

    /**
     * Nodes a and b offer the behaviour; a asks with the event's fields and b's installer answers 400 ms after the
     * question, later than install.bid.ms (100 ms).
     *
     * @param bOwnsRobot2 whether b's edge owns robot2
     * @return the nodes of the candidates a's fabric installer chose
     */
    private List<String> choiceWithBAnsweringLate(Map<String, Object> event, boolean bOwnsRobot2) throws Exception {
        TestNode[] aRef = new TestNode[1];
        TestNode[] bRef = new TestNode[1];
        FakeInstaller atB = offering(bRef, new Recorder());
        aRef[0] = node("a", offering(aRef, new Recorder()));
        bRef[0] = node("b", atB);
        if (bOwnsRobot2) {
            ((FabricInstaller) bRef[0].fabric.installer()).ownedDevices("robot2"::equals);
        }
        awaitOnline(aRef[0], bRef[0]);
        Deferred<List<BehaviourCandidate>> slow = new Deferred<>();
        atB.findAnswer = slow.getPromise();
        Promise<List<BehaviourCandidate>> found = aRef[0].fabric.installer().find(List.of(MOVED), event);
        CompletableFuture.delayedExecutor(400, TimeUnit.MILLISECONDS)
                .execute(() -> slow.resolve(List.of(FakeInstaller.candidate(RECORDER, MOVED))));
        return found.timeout(10_000).getValue().stream().map(cand -> cand.node).toList();
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void theChosenNodeGoingOfflineMidInstallFailsTheInstallNamingIt(Broker.Kind kind) throws Exception {
        startBroker(kind);
        FakeInstaller atA = new FakeInstaller();
        FakeInstaller atB = new FakeInstaller();
        atB.offers = Map.of(MOVED, FakeInstaller.candidate(RECORDER, MOVED));
        Deferred<InstalledBehaviour> never = new Deferred<>();
        atB.onInstall = r -> never.getPromise(); // b starts installing and never finishes: it dies meanwhile
        TestNode a = node("a", atA);
        TestNode b = node("b", atB);
        awaitOnline(a, b);
        MiniBms bms = new MiniBms(a.fabric.installer(), MOVED);
        a.bus.policy(bms);

        a.bus.deliver(new Moved("r1", 1));
        await("b got the install order").atMost(DEADLINE).until(() -> atB.installs.size() == 1);
        b.crash(); // no goodbye: the broker publishes b's Last Will within 1.5 keep-alives

        ExecutionException failed = org.junit.jupiter.api.Assertions.assertThrows(ExecutionException.class,
                () -> bms.outcome.get(30, TimeUnit.SECONDS));
        assertThat(failed.getCause()).isInstanceOf(InstallException.class)
                .hasMessageContaining("node b went offline while installing " + RECORDER);
        assertThat(((InstallException) failed.getCause()).problem()).isEqualTo(InstallException.Problem.START_FAILED);
        assertThat(a.bus.held()).as("the events stay held: the BMS chooses again or gives up").isNotEmpty();
    }

    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void withNoAnswerByTheDeadlineTheLocalInstallerIsUsed(Broker.Kind kind) throws Exception {
        startBroker(kind);
        Recorder recorder = new Recorder();
        TestNode[] aRef = new TestNode[1];
        FakeInstaller atA = offering(aRef, recorder);
        FakeInstaller atB = new FakeInstaller();
        atB.findAnswer = new Deferred<List<BehaviourCandidate>>().getPromise(); // b never answers
        aRef[0] = node("a", atA);
        TestNode a = aRef[0];
        TestNode b = node("b", atB);
        awaitOnline(a, b);

        long start = System.nanoTime();
        Promise<List<BehaviourCandidate>> found = a.fabric.installer().find(List.of(MOVED));
        List<BehaviourCandidate> candidates = found.getValue();
        long took = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertThat(candidates).extracting(cand -> cand.node).containsExactly("a");
        assertThat(took).as("decided at the deadline (100 ms), not before b's answer could come").isBetween(90L,
                5_000L);

        MiniBms bms = new MiniBms(a.fabric.installer(), MOVED);
        a.bus.policy(bms);
        for (int i = 1; i <= 50; i++) {
            a.bus.deliver(new Moved("r1", i));
        }
        bms.outcome.get(30, TimeUnit.SECONDS);
        await().atMost(DEADLINE).until(() -> recorder.got.size() == 50);
        assertThat(recorder.seqs()).containsExactlyElementsOf(LongStream.rangeClosed(1, 50).boxed().toList());
        assertThat(atA.installs).hasSize(1);
        assertThat(atB.installs).isEmpty();
    }

    /**
     * The only node that offers the behaviour answers after the bid's deadline (a node under load): with no candidate
     * offered yet, the asking node waits for it rather than give the events up.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void aLateOfferIsWaitedForWhenNoOtherNodeOffersACandidate(Broker.Kind kind) throws Exception {
        startBroker(kind);
        Recorder recorder = new Recorder();
        TestNode[] bRef = new TestNode[1];
        FakeInstaller atA = new FakeInstaller(); // nothing for it
        FakeInstaller atB = offering(bRef, recorder);
        Deferred<List<BehaviourCandidate>> late = new Deferred<>();
        atB.findAnswer = late.getPromise();
        TestNode a = node("a", atA);
        bRef[0] = node("b", atB);
        awaitOnline(a, bRef[0]);

        Promise<List<BehaviourCandidate>> found = a.fabric.installer().find(List.of(MOVED));
        await("still waiting for b, the only node left to answer, past the bid's deadline (100 ms)")
                .during(Duration.ofMillis(400)).atMost(DEADLINE).until(() -> !found.isDone());
        late.resolve(List.of(FakeInstaller.candidate(RECORDER, MOVED)));
        assertThat(found.getValue()).extracting(cand -> cand.node).containsExactly("b");
    }

    /**
     * The receiving node is killed and, once the others saw its Last Will, started again with its state: the events
     * published meanwhile, which no node online takes, are held by the publisher's BMS for it (its last interest
     * took them) and reach it when it is back, with every other event: once each, in publish order.
     */
    @ParameterizedTest
    @EnumSource(Broker.Kind.class)
    void eventsPublishedWhileTheirNodeIsDownReachItWhenItIsBack(Broker.Kind kind) throws Exception {
        startBroker(kind);
        TestNode a = node("a", new FakeInstaller()); // no repository offers the behaviour: only b has it
        Recorder before = new Recorder();
        TestNode b = new TestNode("b", settings("b"));
        nodes.add(b);
        b.addBehaviour(before, null, MOVED);
        b.start();
        b.fabric.localInstaller(new FakeInstaller());
        awaitOnline(a, b);
        await("b's interest seen by a").atMost(DEADLINE).until(() -> a.fabric.nodes().stream()
                .anyMatch(v -> v.node().equals("b") && !v.interest().isEmpty()));
        MiniBms bms = new MiniBms(a.fabric.installer(), MOVED);
        a.bus.policy(bms);
        for (int i = 1; i <= 100; i++) {
            a.bus.deliver(new Moved("r1", i));
        }
        await().atMost(DEADLINE).until(() -> before.got.size() == 100);

        b.crash();
        await("b offline for a (its Last Will)").atMost(DEADLINE).until(() -> a.statusOf("b").equals("offline"));
        for (int i = 101; i <= 300; i++) {
            a.bus.deliver(new Moved("r1", i)); // nobody online takes them
        }
        assertThat(bms.found.get(30, TimeUnit.SECONDS)).extracting(cand -> cand.node).containsExactly("b");

        Recorder after = new Recorder();
        TestNode b2 = new TestNode("b", settings("b")); // started again with its state
        nodes.add(b2);
        b2.addBehaviour(after, null, MOVED);
        b2.start();
        b2.fabric.localInstaller(new FakeInstaller());
        bms.outcome.get(30, TimeUnit.SECONDS);
        for (int i = 301; i <= 400; i++) {
            a.bus.deliver(new Moved("r1", i));
        }
        await().atMost(DEADLINE).until(() -> after.got.size() >= 300);
        await().during(Duration.ofMillis(300)).atMost(DEADLINE).until(() -> after.got.size() == 300);
        assertThat(after.seqs()).as("the held events and the newer ones, once each, in publish order")
                .containsExactlyElementsOf(LongStream.rangeClosed(101, 400).boxed().toList());
        assertThat(a.bus.held()).isEmpty();
        assertThat(a.log).anyMatch(l -> l.contains("wait for node b"));
    }

    @Override
    Settings settings(String name) {
        return super.settings(name).withInstall(100, 30_000);
    }

    @Test
    void aloneTheNodesOwnInstallerAnswersAsItIs() throws Exception {
        startBroker(Broker.Kind.HIVEMQ);
        FakeInstaller own = new FakeInstaller();
        own.offers = Map.of(MOVED, FakeInstaller.candidate(RECORDER, MOVED));
        TestNode a = node("a", own);
        await().atMost(DEADLINE).until(() -> a.fabric.joined());
        Promise<List<BehaviourCandidate>> found = a.fabric.installer().find(List.of(MOVED));
        assertThat(found.isDone()).as("answered from memory, at once, as the node's own installer").isTrue();
        assertThat(found.getValue()).extracting(cand -> cand.node).containsExactly((String) null);
        InstalledBehaviour done = a.fabric.installer().install(new eu.brain.iot.bis.api.InstallRequest())
                .getValue();
        assertThat(done.symbolicName).isNull();
        assertThat(own.installs).hasSize(1);
    }
}
