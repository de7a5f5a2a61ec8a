package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;

/** {@code tryDeliver}: never waits, refuses all or nothing, and is {@code deliver} in everything else. */
class TryDeliverTest {

    static final Duration DEADLINE = Duration.ofSeconds(20);
    /** Long enough that a publisher that waited for room would be seen to wait. */
    static final long OVERFLOW_MILLIS = 10_000;
    static final int CAPACITY = 4;

    public static class Tick extends BrainIoTEvent {
        public int seq;

        public Tick() {
        }

        Tick(int seq) {
            this.seq = seq;
        }
    }

    /** Blocks in its first notify() until released; keeps what it received, in order. */
    static final class Gate implements SmartBehaviour<Tick> {
        final CountDownLatch entered = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);
        final List<Integer> received = new CopyOnWriteArrayList<>();

        @Override
        public void notify(Tick event) {
            entered.countDown();
            try {
                release.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            received.add(event.seq);
        }
    }

    static final class Recorder implements SmartBehaviour<Tick> {
        final List<Integer> received = new CopyOnWriteArrayList<>();

        @Override
        public void notify(Tick event) {
            received.add(event.seq);
        }
    }

    final RecordingLogger log = new RecordingLogger();
    final AtomicLong ids = new AtomicLong();
    final AsyncEventBus bus = new AsyncEventBus("node", CAPACITY, OVERFLOW_MILLIS, new DeliveryPool.Settings(2,
            TimeUnit.MICROSECONDS.toNanos(50), TimeUnit.MILLISECONDS.toNanos(5), TimeUnit.SECONDS.toNanos(1)),
            log.logger);

    @AfterEach
    void tearDown() {
        bus.close();
    }

    private void add(Object behaviour) {
        long id = ids.incrementAndGet();
        bus.addConsumer(new ConsumerSpec(id, "b#" + id, "test.bundle", Set.of(Tick.class.getName()), null, false,
                false, BehaviourHandle.of(behaviour), className -> Tick.class.getName().equals(className) ? Tick.class
                        : null));
    }

    /** Fills the gate's queue: one event inside notify(), CAPACITY waiting; returns the next sequence number. */
    private int fill(Gate gate) throws InterruptedException {
        assertThat(bus.tryDeliver(new Tick(0))).isTrue();
        assertThat(gate.entered.await(DEADLINE.toMillis(), TimeUnit.MILLISECONDS)).isTrue();
        for (int seq = 1; seq <= CAPACITY; seq++) {
            assertThat(bus.tryDeliver(new Tick(seq))).as("event %d fits in the queue", seq).isTrue();
        }
        return CAPACITY + 1;
    }

    @Test
    void aFullQueueIsRefusedAtOnceAndForEveryConsumer() throws Exception {
        Gate gate = new Gate();
        add(gate);
        int next = fill(gate);
        Recorder other = new Recorder(); // has room for everything
        add(other);

        long start = System.nanoTime();
        for (int i = 0; i < 1_000; i++) {
            assertThat(bus.tryDeliver(new Tick(next))).isFalse();
        }
        long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        // a thousand refusals, each of which would have waited OVERFLOW_MILLIS with deliver()
        assertThat(tookMillis).isLessThan(OVERFLOW_MILLIS);
        assertThat(bus.consumers()).extracting(c -> c.queueDepth).as("all or none: the consumer with room got "
                + "none of the refused events").containsExactlyInAnyOrder(CAPACITY, 0);

        gate.release.countDown();
        await().atMost(DEADLINE).until(() -> gate.received.size() == next);
        assertThat(bus.tryDeliver(new Tick(next))).isTrue();
        await().atMost(DEADLINE).until(() -> gate.received.size() == next + 1 && other.received.size() == 1);
        assertThat(gate.received).containsExactly(0, 1, 2, 3, 4, 5);
        assertThat(other.received).containsExactly(5);
        assertThat(bus.eventTypes()).singleElement().satisfies(s -> {
            assertThat(s.published).as("refused events are not counted as published").isEqualTo(next + 1);
            assertThat(s.discarded).isZero();
        });
    }

    @Test
    void untypedEventsAreRefusedTheSameWay() throws Exception {
        Gate gate = new Gate();
        add(gate);
        int next = fill(gate);
        assertThat(bus.tryDeliver(Tick.class.getName(), Map.of("seq", next))).isFalse();
        gate.release.countDown();
        await().atMost(DEADLINE).until(() -> gate.received.size() == next);
        assertThat(bus.tryDeliver(Tick.class.getName(), Map.of("seq", next))).isTrue();
        await().atMost(DEADLINE).until(() -> gate.received.size() == next + 1);
        assertThat(gate.received).endsWith(next);
    }

    @Test
    void anEventNoOneTakesIsAcceptedAndAFullHoldIsRefusedAtOnce() {
        assertThat(bus.tryDeliver(new Tick(1))).as("no consumer, no policy: counted as unhandled").isTrue();
        UnhandledEventPolicy policy = new UnhandledEventPolicy() {
            @Override
            public Disposition unhandled(String eventType, List<String> typeHierarchy) {
                return Disposition.HOLD;
            }

            @Override
            public int maxHeldEvents() {
                return 2;
            }
        };
        bus.policy(policy);
        assertThat(bus.tryDeliver(new Tick(2))).isTrue();
        assertThat(bus.tryDeliver(new Tick(3))).isTrue();
        long start = System.nanoTime();
        assertThat(bus.tryDeliver(new Tick(4))).as("the hold is full").isFalse();
        assertThat(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start)).isLessThan(OVERFLOW_MILLIS);
        assertThat(bus.held()).singleElement().satisfies(h -> assertThat(h.count).isEqualTo(2));

        Recorder late = new Recorder();
        add(late);
        await().atMost(DEADLINE).until(() -> late.received.size() == 2);
        assertThat(late.received).containsExactly(2, 3);
    }
}
