package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.spi.EventForwarder;

/**
 * The bus's side of a fabric: forwarders are routed like behaviours (supertypes, filters), one copy per destination;
 * events from another node reach local behaviours only, and their completion runs after {@code notify} returned.
 */
class ForwardingTest {

    static final Duration DEADLINE = Duration.ofSeconds(20);

    public static class Moved extends BrainIoTEvent {
        public String robotId;

        public Moved() {
        }

        Moved(String robotId) {
            this.robotId = robotId;
        }
    }

    public static class Docked extends Moved {
        public Docked() {
        }

        Docked(String robotId) {
            super(robotId);
        }
    }

    static final class Recorder implements EventForwarder {
        final List<String> got = new CopyOnWriteArrayList<>();
        final List<List<String>> names = new CopyOnWriteArrayList<>();

        @Override
        public void forward(String eventType, List<String> typeNames, Map<String, Object> properties) {
            got.add(eventType + ":" + properties.get("robotId"));
            names.add(typeNames);
        }
    }

    /** A node that takes one event, then no more until {@code leave} (at most 20 s). */
    static EventForwarder takesOneThenWaits(CountDownLatch inside, CountDownLatch leave) {
        return (type, names, data) -> {
            inside.countDown();
            try {
                leave.await(20, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        };
    }

    final RecordingLogger log = new RecordingLogger();
    final BusCore bus = new BusCore(16, 1_000, log.logger);

    @AfterEach
    void close() {
        bus.close();
    }

    @Test
    void forwardersAreRoutedLikeBehavioursOneCopyPerDestination() {
        Recorder nodeB = new Recorder();
        Recorder nodeC = new Recorder();
        bus.addForwarder(nodeB, "B", null, Moved.class.getName());
        bus.addForwarder(nodeB, "B", "(robotId=r1)", Docked.class.getName()); // overlaps the first: one copy only
        bus.addForwarder(nodeC, "C", "(robotId=r2)", Moved.class.getName());

        bus.deliver(new Docked("r1"));
        bus.deliver(new Moved("r2"));

        await().atMost(DEADLINE).until(() -> nodeB.got.size() == 2 && nodeC.got.size() == 1);
        assertThat(nodeB.got).containsExactly(Docked.class.getName() + ":r1", Moved.class.getName() + ":r2");
        assertThat(nodeB.names.get(0)).startsWith(Docked.class.getName(), Moved.class.getName());
        assertThat(nodeC.got).containsExactly(Moved.class.getName() + ":r2");
    }

    /** Takes events on the publisher's thread while {@code room} lasts; the rest on a delivery worker. */
    static final class TakesWhileRoom implements EventForwarder {
        final AtomicInteger room;
        final List<String> got = new CopyOnWriteArrayList<>();
        final List<Thread> threads = new CopyOnWriteArrayList<>();
        final List<Boolean> now = new CopyOnWriteArrayList<>();

        TakesWhileRoom(int room) {
            this.room = new AtomicInteger(room);
        }

        @Override
        public void forward(String eventType, List<String> typeNames, Map<String, Object> properties) {
            record(properties, false);
        }

        @Override
        public boolean forwardNow(String eventType, List<String> typeNames, Map<String, Object> properties) {
            if (room.getAndDecrement() <= 0) {
                return false;
            }
            record(properties, true);
            return true;
        }

        private void record(Map<String, Object> properties, boolean onPublisher) {
            got.add((String) properties.get("robotId"));
            threads.add(Thread.currentThread());
            now.add(onPublisher);
        }
    }

    @Test
    void anIdleForwarderTakesTheEventOnThePublishersThread() {
        TakesWhileRoom nodeB = new TakesWhileRoom(Integer.MAX_VALUE);
        bus.addForwarder(nodeB, "B", null, Moved.class.getName());

        bus.deliver(new Moved("r1"));
        assertThat(bus.tryDeliver(new Moved("r2"))).isTrue();

        assertThat(nodeB.got).as("taken before deliver and tryDeliver returned").containsExactly("r1", "r2");
        assertThat(nodeB.threads).containsOnly(Thread.currentThread());
        assertThat(bus.statistics(Moved.class.getName()).delivered).isEqualTo(2);
    }

    @Test
    void whatAForwarderRefusesOnThePublishersThreadReachesItOnADeliveryWorkerInOrder() {
        TakesWhileRoom nodeB = new TakesWhileRoom(3);
        bus.addForwarder(nodeB, "B", null, Moved.class.getName());

        for (int i = 1; i <= 8; i++) {
            bus.deliver(new Moved("r" + i));
        }

        await().atMost(DEADLINE).until(() -> nodeB.got.size() == 8);
        assertThat(nodeB.got).containsExactly("r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8");
        assertThat(nodeB.now.subList(0, 3)).containsOnly(true);
        assertThat(nodeB.threads.subList(0, 3)).containsOnly(Thread.currentThread());
        assertThat(nodeB.now.subList(3, 8)).as("refused: each once, then taken by forward()").containsOnly(false);
        assertThat(nodeB.threads.subList(3, 8)).doesNotContain(Thread.currentThread());
    }

    @Test
    void aForwarderThatFailsOnThePublishersThreadIsCountedAndTheEventIsNotForwardedAgain() {
        AtomicInteger calls = new AtomicInteger();
        bus.addForwarder(new EventForwarder() {
            @Override
            public void forward(String eventType, List<String> typeNames, Map<String, Object> properties) {
                calls.incrementAndGet();
            }

            @Override
            public boolean forwardNow(String eventType, List<String> typeNames, Map<String, Object> properties) {
                calls.incrementAndGet();
                throw new IllegalStateException("the fabric connection is closed");
            }
        }, "B", null, Moved.class.getName());

        bus.deliver(new Moved("r1"));

        assertThat(calls.get()).isEqualTo(1);
        assertThat(bus.statistics(Moved.class.getName()).failed).isEqualTo(1);
        assertThat(log.count("error", "failed on an event of type")).isEqualTo(1);
    }

    @Test
    void remoteEventsReachLocalBehavioursOnlyAndCompleteAfterNotify() throws Exception {
        Recorder forwarder = new Recorder();
        bus.addForwarder(forwarder, "B", null, Moved.class.getName());
        CountDownLatch inside = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        List<String> seen = new CopyOnWriteArrayList<>();
        bus.addUntypedBehaviour((UntypedSmartBehaviour) (type, fields) -> {
            inside.countDown();
            try {
                release.await(20, TimeUnit.SECONDS);
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            }
            seen.add(type + ":" + fields.get("robotId"));
        }, null, Moved.class.getName());
        AtomicInteger done = new AtomicInteger();

        // a subtype the receiving node routes by its supertype, as the publishing node named them
        boolean accepted = bus.tryDeliverRemote("some.remote.Docked",
                List.of("some.remote.Docked", Moved.class.getName()), Map.of("robotId", "r9"), done::incrementAndGet);

        assertThat(accepted).isTrue();
        assertThat(inside.await(20, TimeUnit.SECONDS)).isTrue();
        assertThat(done.get()).as("not done while notify() runs").isZero();
        release.countDown();
        await().atMost(DEADLINE).until(() -> done.get() == 1);
        assertThat(seen).containsExactly("some.remote.Docked:r9");
        assertThat(forwarder.got).as("an event from another node is never forwarded again").isEmpty();
    }

    @Test
    void eventsQueuedForAForwarderThatGoesAwayArePublishedAgainNotDiscarded() throws Exception {
        CountDownLatch inside = new CountDownLatch(1);
        long id = bus.addForwarder(takesOneThenWaits(inside, new CountDownLatch(1)), "B", null, Moved.class.getName());
        for (int i = 1; i <= 5; i++) {
            bus.deliver(new Moved("r" + i));
        }
        assertThat(inside.await(20, TimeUnit.SECONDS)).isTrue();

        bus.removeBehaviour(id); // its node left: the 4 events still queued go to whoever takes them now (nobody)

        await().atMost(DEADLINE).until(() -> bus.statistics(Moved.class.getName()).unhandled == 4);
        assertThat(bus.statistics(Moved.class.getName()).discarded).isZero();
    }

    @Test
    void eventsQueuedForAForwarderThatGoesAwayKeepTheirPlaceBeforeLaterOnes() throws Exception {
        EventHoldTest.Policy policy = new EventHoldTest.Policy(); // holds every unhandled event
        bus.policy(policy);
        CountDownLatch inside = new CountDownLatch(1);
        CountDownLatch leave = new CountDownLatch(1);
        Recorder forwarded = new Recorder();
        long id = bus.addForwarder((EventForwarder) (type, names, data) -> {
            forwarded.forward(type, names, data);
            inside.countDown();
            boolean interrupted = false;
            while (leave.getCount() > 0) { // a forwarder that does not return at once when its node leaves
                try {
                    leave.await();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }, "B", null, Moved.class.getName());
        for (int i = 1; i <= 5; i++) {
            bus.deliver(new Moved("r" + i));
        }
        assertThat(inside.await(20, TimeUnit.SECONDS)).isTrue();

        bus.removeBehaviour(id); // r2..r5 still queued for it
        for (int i = 6; i <= 8; i++) {
            bus.deliver(new Moved("r" + i)); // held: nobody takes them now
        }
        leave.countDown();
        List<String> seen = new CopyOnWriteArrayList<>();
        bus.addForwarder((EventForwarder) (type, names, data) -> seen.add((String) data.get("robotId")), "B", null,
                Moved.class.getName());

        await().atMost(DEADLINE).until(() -> seen.size() == 7);
        assertThat(forwarded.got).containsExactly(Moved.class.getName() + ":r1");
        assertThat(seen).as("the events queued for the forwarder that left come before those published after")
                .containsExactly("r2", "r3", "r4", "r5", "r6", "r7", "r8");
    }

    @Test
    void anEventRoutedToAForwarderAsItLeavesIsPublishedOnceInOrderToWhoeverTakesItNow() throws Exception {
        int capacity = 2_048;
        BusCore wide = new BusCore(capacity, 20_000, log.logger);
        try {
            wide.policy(new EventHoldTest.Policy()); // holds what nobody takes, as the BMS does for a node away
            AtomicInteger attempted = new AtomicInteger();
            AtomicInteger accepted = new AtomicInteger();
            AtomicReference<Throwable> failed = new AtomicReference<>();
            AtomicBoolean stop = new AtomicBoolean();
            // a small stack, as a busy thread may have: publishing again must not recurse while the table changes
            Thread publisher = new Thread(null, () -> {
                try {
                    while (!stop.get()) {
                        wide.deliver(new Moved("r" + attempted.incrementAndGet()));
                        accepted.incrementAndGet();
                    }
                } catch (Throwable t) {
                    failed.set(t);
                }
            }, "publisher", 256 * 1024);
            Set<String> seen = ConcurrentHashMap.newKeySet();
            List<String> duplicates = new CopyOnWriteArrayList<>();
            List<Integer> order = new CopyOnWriteArrayList<>();
            EventForwarder recorder = (type, names, data) -> {
                order.add(Integer.parseInt(((String) data.get("robotId")).substring(1)));
                if (!seen.add((String) data.get("robotId"))) {
                    duplicates.add((String) data.get("robotId"));
                }
            };
            publisher.start();
            for (int round = 1; round <= 5; round++) {
                CountDownLatch leave = new CountDownLatch(1);
                long id = wide.addForwarder((EventForwarder) (type, names, data) -> {
                    recorder.forward(type, names, data);
                    try {
                        leave.await(20, TimeUnit.SECONDS); // its node takes no more: the queue fills
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }, "B", null, Moved.class.getName());
                // the publisher waits for room in the full queue of the forwarder that is about to leave
                await().atMost(DEADLINE).until(() -> failed.get() != null
                        || wide.queueDepth(id) >= capacity && attempted.get() == accepted.get() + 1);
                assertThat(failed.get()).isNull();
                wide.removeBehaviour(id);
                leave.countDown();
            }
            stop.set(true);
            wide.addForwarder(recorder, "B", null, Moved.class.getName());
            publisher.join(DEADLINE.toMillis());

            assertThat(failed.get()).as("the publisher's error").isNull();
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(seen).as("events forwarded, of %d accepted; bus: %s",
                    accepted.get(), wide.statistics(Moved.class.getName())).hasSize(accepted.get()));
            assertThat(duplicates).isEmpty();
            assertThat(order).as("in the order published").isSorted();
        } finally {
            wide.close();
        }
    }

    @Test
    void aForwarderThatLeavesHandsItsEventsToNoConsumerThatHadThemAlready() throws Exception {
        EventHoldTest.Policy policy = new EventHoldTest.Policy();
        bus.policy(policy);
        List<String> local = new CopyOnWriteArrayList<>();
        bus.addUntypedBehaviour((UntypedSmartBehaviour) (type, fields) -> local.add((String) fields.get("robotId")),
                null, Moved.class.getName());
        CountDownLatch inside = new CountDownLatch(1);
        CountDownLatch leave = new CountDownLatch(1);
        long id = bus.addForwarder(takesOneThenWaits(inside, leave), "B", null, Moved.class.getName());
        for (int i = 1; i <= 5; i++) {
            bus.deliver(new Moved("r" + i));
        }
        assertThat(inside.await(20, TimeUnit.SECONDS)).isTrue();
        await().atMost(DEADLINE).until(() -> local.size() == 5);

        bus.removeBehaviour(id); // r2..r5 still queued for it: the local behaviour had them already
        leave.countDown();
        List<String> seen = new CopyOnWriteArrayList<>();
        bus.addForwarder((EventForwarder) (type, names, data) -> seen.add((String) data.get("robotId")), "B", null,
                Moved.class.getName());
        bus.deliver(new Moved("r6"));

        await().atMost(DEADLINE).until(() -> seen.size() == 5);
        assertThat(seen).containsExactly("r2", "r3", "r4", "r5", "r6");
        await().atMost(DEADLINE).until(() -> local.size() == 6);
        assertThat(local).containsExactly("r1", "r2", "r3", "r4", "r5", "r6");
    }

    @Test
    void aRemoteEventNoBehaviourTakesIsDoneAtOnce() {
        AtomicInteger done = new AtomicInteger();
        assertThat(bus.tryDeliverRemote("x.Unknown", List.of(), Map.of("a", 1), done::incrementAndGet)).isTrue();
        assertThat(done.get()).isEqualTo(1);
        assertThat(bus.statistics("x.Unknown").unhandled).isEqualTo(1);
    }

    @Test
    void toBehavioursOnlyARemoteEventNoBehaviourTakesIsNotAccepted() {
        AtomicInteger done = new AtomicInteger();
        assertThat(bus.tryDeliverRemoteToBehaviours("x.Unknown", List.of(), Map.of("a", 1), done::incrementAndGet))
                .as("offered again later").isFalse();
        assertThat(done.get()).isZero();
        assertThat(bus.statistics("x.Unknown").unhandled).isZero();
    }

    /** An untyped local behaviour that records the robot of every event it takes. */
    static final class Local implements UntypedSmartBehaviour {
        final List<String> got = new CopyOnWriteArrayList<>();

        @Override
        public void notify(String eventType, Map<String, ?> properties) {
            got.add((String) properties.get("robotId"));
        }
    }

    @Test
    void anEventGivenUpReachesOnlyTheConsumersRegisteredSinceItWasPublished() {
        Recorder oldNode = new Recorder();
        Local oldLocal = new Local();
        bus.addForwarder(oldNode, "B", null, Moved.class.getName());
        bus.addUntypedBehaviour(oldLocal, null, Moved.class.getName());
        long published = System.currentTimeMillis();
        await("the clock moves on").atMost(DEADLINE).until(() -> System.currentTimeMillis() > published);
        Recorder newNode = new Recorder();
        Local newLocal = new Local();
        bus.addForwarder(newNode, "C", null, Moved.class.getName());
        bus.addUntypedBehaviour(newLocal, "(robotId=r1)", Moved.class.getName());

        List<String> names = List.of(Docked.class.getName(), Moved.class.getName());
        assertThat(bus.tryDeliverGivenUp(Docked.class.getName(), names, Map.of("robotId", "r1"), published)).isTrue();

        await().atMost(DEADLINE).until(() -> newNode.got.size() == 1 && newLocal.got.size() == 1);
        assertThat(newNode.got).containsExactly(Docked.class.getName() + ":r1");
        assertThat(newLocal.got).containsExactly("r1");
        assertThat(oldNode.got).as("had it when it was published").isEmpty();
        assertThat(oldLocal.got).as("had it when it was published").isEmpty();
    }

    @Test
    void anEventGivenUpThatOnlyOlderConsumersTakeGoesNowhereAndOneNobodyTakesIsUnhandled() {
        Local oldLocal = new Local();
        bus.addUntypedBehaviour(oldLocal, null, Moved.class.getName());
        long later = System.currentTimeMillis() + 60_000;

        assertThat(bus.tryDeliverGivenUp(Moved.class.getName(), List.of(), Map.of("robotId", "r1"), later)).isTrue();
        assertThat(bus.tryDeliverGivenUp(Docked.class.getName() + "X", List.of(), Map.of("robotId", "r2"), later))
                .isTrue();

        assertThat(bus.statistics(Docked.class.getName() + "X").unhandled).isEqualTo(1);
        assertThat(bus.statistics(Moved.class.getName()).unhandled).isZero();
        assertThat(oldLocal.got).isEmpty();
    }
}
