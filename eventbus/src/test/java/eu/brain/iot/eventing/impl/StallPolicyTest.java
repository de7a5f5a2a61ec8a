package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Future;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.impl.TryDeliverTest.Gate;
import eu.brain.iot.eventing.impl.TryDeliverTest.Recorder;
import eu.brain.iot.eventing.impl.TryDeliverTest.Tick;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;

/**
 * A stalled behaviour (queue full, notify() not returned for the overflow timeout) stops taking events so that
 * the other consumers of its types keep theirs; a merely slow one still pushes back on publishers.
 */
class StallPolicyTest {

    static final Duration DEADLINE = Duration.ofSeconds(20);
    static final int CAPACITY = 4;
    static final long OVERFLOW_MILLIS = 200;
    static final long SLOW_OVERFLOW_MILLIS = 150;
    static final long SLOW_NOTIFY_MILLIS = 30;
    static final int PUBLISHERS = 8;
    static final int EVENTS_EACH = 10;

    final RecordingLogger log = new RecordingLogger();
    final AtomicLong ids = new AtomicLong();
    AsyncEventBus bus = bus(OVERFLOW_MILLIS);

    private AsyncEventBus bus(long overflowMillis) {
        return new AsyncEventBus("node", CAPACITY, overflowMillis, new DeliveryPool.Settings(2,
                TimeUnit.MICROSECONDS.toNanos(50), TimeUnit.MILLISECONDS.toNanos(5), TimeUnit.SECONDS.toNanos(1)),
                log.logger);
    }

    @AfterEach
    void tearDown() {
        bus.close();
    }

    private String add(Object behaviour) {
        long id = ids.incrementAndGet();
        bus.addConsumer(new ConsumerSpec(id, "b#" + id, "test.bundle", Set.of(Tick.class.getName()), null, false,
                false, BehaviourHandle.of(behaviour), className -> null));
        return "b#" + id;
    }

    private ConsumerStatistics stats(String name) {
        return bus.consumers().stream().filter(c -> c.consumer.equals(name)).findFirst().orElseThrow();
    }

    @Test
    void aStalledBehaviourIsSkippedSoThatTheOthersKeepTheirsAndItResumesWhenNotifyReturns() throws Exception {
        Gate stuck = new Gate();
        String stuckName = add(stuck);
        Recorder healthy = new Recorder();
        String healthyName = add(healthy);
        bus.deliver(new Tick(0));
        assertThat(stuck.entered.await(DEADLINE.toMillis(), TimeUnit.MILLISECONDS)).isTrue();
        for (int seq = 1; seq <= CAPACITY; seq++) {
            bus.deliver(new Tick(seq)); // fills the stuck behaviour's queue
        }
        assertThat(stats(stuckName).stalled).isFalse();

        long start = System.nanoTime();
        for (int seq = CAPACITY + 1; seq < 100; seq++) {
            bus.deliver(new Tick(seq)); // no EventBusOverflowException: the stalled behaviour is skipped
        }
        assertThat(Duration.ofNanos(System.nanoTime() - start)).as("the first publisher waited the overflow timeout")
                .isGreaterThanOrEqualTo(Duration.ofMillis(OVERFLOW_MILLIS));
        await().atMost(DEADLINE).until(() -> healthy.received.size() == 100);

        ConsumerStatistics stalled = stats(stuckName);
        assertThat(stalled.stalled).isTrue();
        assertThat(stalled.discarded).isEqualTo(100 - CAPACITY - 1);
        assertThat(stats(healthyName).stalled).isFalse();
        assertThat(bus.eventTypes()).singleElement().satisfies(s -> {
            assertThat(s.published).isEqualTo(100);
            assertThat(s.discarded).isEqualTo(100 - CAPACITY - 1);
        });
        assertThat(log.count("error", "is stalled")).isEqualTo(1);

        stuck.release.countDown();
        await().atMost(DEADLINE).until(() -> stuck.received.size() == CAPACITY + 1);
        await().atMost(DEADLINE).until(() -> !stats(stuckName).stalled);
        assertThat(log.count("warn", "takes events again")).isEqualTo(1);
        bus.deliver(new Tick(100));
        await().atMost(DEADLINE).until(() -> stuck.received.size() == CAPACITY + 2);
        assertThat(stuck.received).containsExactly(0, 1, 2, 3, 4, 100);
    }

    @Test
    void tryDeliverSkipsAStalledBehaviourOnceItIsKnownStalled() throws Exception {
        Gate stuck = new Gate();
        String stuckName = add(stuck);
        bus.deliver(new Tick(0));
        assertThat(stuck.entered.await(DEADLINE.toMillis(), TimeUnit.MILLISECONDS)).isTrue();
        for (int seq = 1; seq <= CAPACITY; seq++) {
            bus.deliver(new Tick(seq));
        }
        assertThat(bus.tryDeliver(new Tick(5))).as("full, not yet stalled: refused at once").isFalse();
        bus.deliver(new Tick(6)); // waits the overflow timeout, finds it stalled
        assertThat(bus.tryDeliver(new Tick(7))).as("stalled: accepted, discarded for it").isTrue();
        assertThat(stats(stuckName).discarded).isEqualTo(2);
        stuck.release.countDown();
    }

    @Test
    void aSlowBehaviourStillPushesBackOnPublishersAndLosesNothing() {
        List<Integer> got = new CopyOnWriteArrayList<>();
        SmartBehaviour<Tick> slow = tick -> {
            long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(10);
            while (System.nanoTime() < until) {
                Thread.onSpinWait(); // slow by design: it computes for 10 ms per event
            }
            got.add(tick.seq);
        };
        String name = add(slow);
        long start = System.nanoTime();
        for (int seq = 0; seq < 40; seq++) {
            bus.deliver(new Tick(seq));
        }
        assertThat(Duration.ofNanos(System.nanoTime() - start)).as("the publisher waited for the slow behaviour")
                .isGreaterThanOrEqualTo(Duration.ofMillis(10L * (40 - CAPACITY - 1)));
        await().atMost(DEADLINE).until(() -> got.size() == 40);
        assertThat(stats(name).discarded).isZero();
        assertThat(stats(name).stalled).isFalse();
        assertThat(log.count("error", "is stalled")).isZero();
    }

    @Test
    void deliverStillThrowsWhenASlowBehaviourMakesNoRoomForItInTime() throws Exception {
        bus.close();
        // A notify of 30 ms against an overflow timeout five times longer: under a loaded machine the behaviour
        // still takes an event well within the timeout (never stalled), while eight publishers share one freed
        // slot per notify, so that some of them find no room within the timeout.
        bus = bus(SLOW_OVERFLOW_MILLIS);
        AtomicInteger got = new AtomicInteger();
        SmartBehaviour<Tick> slow = tick -> {
            try {
                Thread.sleep(SLOW_NOTIFY_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            got.incrementAndGet();
        };
        String name = add(slow);
        ExecutorService publishers = Executors.newFixedThreadPool(PUBLISHERS);
        CountDownLatch go = new CountDownLatch(1);
        List<Future<Integer>> refused = new ArrayList<>();
        for (int p = 0; p < PUBLISHERS; p++) {
            refused.add(publishers.submit(() -> {
                go.await();
                int count = 0;
                for (int i = 0; i < EVENTS_EACH; i++) {
                    try {
                        bus.deliver(new Tick(i));
                    } catch (EventBusOverflowException e) {
                        assertThat(e.getMessage()).contains("stayed full").contains("tryDeliver");
                        count++;
                    }
                }
                return count;
            }));
        }
        go.countDown();
        int total = 0;
        for (Future<Integer> f : refused) {
            total += f.get(DEADLINE.toMillis(), TimeUnit.MILLISECONDS);
        }
        publishers.shutdown();
        assertThat(total).as("a slow behaviour pushes back: publishers that found no room were refused")
                .isPositive();
        assertThat(stats(name).discarded).as("it kept taking events: never stalled, nothing discarded").isZero();
        int accepted = PUBLISHERS * EVENTS_EACH - total;
        await().atMost(DEADLINE).until(() -> got.get() == accepted);
    }
}
