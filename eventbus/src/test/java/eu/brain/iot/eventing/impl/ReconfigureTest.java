package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.impl.DeliveryPoolTest.Tick;

/** The bus's settings change in place: no queued event is lost, workers grow and shrink, capacity applies. */
class ReconfigureTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    final RecordingLogger log = new RecordingLogger();
    final CountDownLatch gate = new CountDownLatch(1);
    AsyncEventBus bus;

    @AfterEach
    void tearDown() {
        gate.countDown();
        if (bus != null) {
            bus.close();
        }
    }

    private static DeliveryPool.Settings settings(int workers) {
        return new DeliveryPool.Settings(workers, TimeUnit.MICROSECONDS.toNanos(50),
                TimeUnit.MILLISECONDS.toNanos(5), TimeUnit.MILLISECONDS.toNanos(100));
    }

    @Test
    void eventsQueuedBehindABlockedBehaviourSurviveReconfigurationsAndWorkersFollowTheSetting() {
        bus = new AsyncEventBus("node", 1_000, 5_000, settings(2), log.logger);
        List<Long> got = new CopyOnWriteArrayList<>();
        SmartBehaviour<Tick> blocked = tick -> {
            try {
                gate.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            got.add(tick.seq);
        };
        bus.addConsumer(new ConsumerSpec(1, "blocked#1", "test.bundle", Set.of(Tick.class.getName()), null, false,
                false, BehaviourHandle.of(blocked), name -> null));
        for (int i = 0; i < 500; i++) {
            bus.deliver(new Tick("p", i));
        }
        bus.reconfigure(600, 200, settings(4));
        await().atMost(DEADLINE).until(() -> bus.workerCount() >= 4);
        bus.reconfigure(500, 200, settings(1));

        // the lower capacity applies to the next reservation at once: the queue (499 or 500 waiting) is full
        for (int i = 500; bus.consumers().get(0).queueDepth < 500; i++) {
            bus.deliver(new Tick("p", i));
        }
        // the new overflow timeout applies: after 200 ms without notify() returning, the behaviour is stalled
        bus.deliver(new Tick("p", -1));
        assertThat(bus.consumers().get(0).stalled).isTrue();

        gate.countDown();
        await().atMost(DEADLINE).until(() -> got.size() == bus.eventTypes().get(0).published - 1);
        for (int i = 0; i < got.size(); i++) {
            assertThat(got.get(i)).isEqualTo(i);
        }
        assertThat(bus.eventTypes().get(0).discarded).as("only the event published while it was stalled")
                .isEqualTo(1);
        // the surplus workers retire once idle (the one blocked before is no longer stalled)
        await().atMost(DEADLINE).until(() -> bus.workerCount() == 1);
    }
}
