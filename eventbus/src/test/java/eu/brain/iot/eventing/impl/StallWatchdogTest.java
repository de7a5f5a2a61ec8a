package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The stall watchdog on a bus with one delivery worker: a behaviour blocked in one call is noticed, named on its
 * worker's thread, logged once and given a replacement worker; a behaviour that keeps making progress is not.
 */
class StallWatchdogTest {

    static final Duration DEADLINE = Duration.ofSeconds(20);

    public static class Tick extends BrainIoTEvent {
        public int seq;
    }

    /** Blocks in every call until opened. */
    static final class Blocker implements SmartBehaviour<Tick> {
        final CountDownLatch open = new CountDownLatch(1);
        final AtomicInteger calls = new AtomicInteger();

        @Override
        public void notify(Tick event) {
            calls.incrementAndGet();
            try {
                open.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    final RecordingLogger log = new RecordingLogger();
    AsyncEventBus bus;

    @AfterEach
    void tearDown() {
        bus.close();
    }

    private AsyncEventBus bus(long thresholdMillis) {
        bus = new AsyncEventBus("node", 1_000, 5_000, new DeliveryPool.Settings(1, 0,
                TimeUnit.MILLISECONDS.toNanos(thresholdMillis), TimeUnit.MILLISECONDS.toNanos(200)), log.logger);
        return bus;
    }

    private void add(long id, String name, Object behaviour) {
        bus.addConsumer(new ConsumerSpec(id, name, "test.bundle", Set.of(Tick.class.getName()), null, false, false,
                BehaviourHandle.of(behaviour), className -> null));
    }

    private static boolean threadNamed(String fragment) {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().contains(fragment));
    }

    @Test
    void aBlockedBehaviourIsNamedOnItsWorkerLoggedOnceAndGivenAnotherWorker() {
        bus(5);
        Blocker blocker = new Blocker();
        add(1, "blocker#1", blocker);
        bus.deliver(new Tick());
        await().atMost(DEADLINE).until(() -> blocker.calls.get() == 1);

        await("the stalled worker named after the behaviour").atMost(DEADLINE)
                .until(() -> threadNamed("brain-iot-bus[blocker#1] stalled in notify()"));
        await("another worker").atMost(DEADLINE).until(() -> bus.workerCount() == 2);
        assertThat(log.count("warn", "has been inside one notify() call")).isEqualTo(1);

        blocker.open.countDown();
        await("the name given back once it returns").atMost(DEADLINE)
                .until(() -> !threadNamed("stalled in notify()"));
        await("the extra worker retires once idle").atMost(DEADLINE).until(() -> bus.workerCount() == 1);

        // a second stall of the same behaviour is not logged again
        Blocker again = blocker;
        bus.deliver(new Tick());
        await().atMost(DEADLINE).until(() -> again.calls.get() == 2); // open: returns at once
        assertThat(log.count("warn", "has been inside one notify() call")).isEqualTo(1);
    }

    @Test
    void aBehaviourThatKeepsTakingEventsIsNotStalledHoweverLongItsTurn() throws Exception {
        bus(200);
        AtomicInteger received = new AtomicInteger();
        add(1, "steady#1", (SmartBehaviour<Tick>) e -> {
            received.incrementAndGet();
            try {
                Thread.sleep(1); // waiting, but well under the threshold each time
            } catch (InterruptedException ie) {
                Thread.currentThread().interrupt();
            }
        });
        for (int i = 0; i < 500; i++) {
            bus.deliver(new Tick());
        }
        await().atMost(DEADLINE).until(() -> received.get() == 500);
        assertThat(log.count("warn", "has been inside one notify() call")).isZero();
        assertThat(bus.workerCount()).isEqualTo(1);
    }
}
