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

    /** How long a call lasts before its stall is logged, in these tests. */
    static final long WARNING_MILLIS = 300;

    private AsyncEventBus bus(long thresholdMillis) {
        bus = new AsyncEventBus("node", 1_000, 5_000, new DeliveryPool.Settings(1, 0,
                TimeUnit.MILLISECONDS.toNanos(thresholdMillis), TimeUnit.MILLISECONDS.toNanos(200),
                TimeUnit.MILLISECONDS.toNanos(WARNING_MILLIS)), log.logger);
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
        await("the stall logged once it lasted the warning time").atMost(DEADLINE)
                .until(() -> log.count("warn", "has been inside one notify() call") == 1);

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
    void aCallShorterThanTheWarningTimeGetsAnotherWorkerButNoWarning() throws Exception {
        bus(5);
        CountDownLatch done = new CountDownLatch(1);
        java.util.concurrent.atomic.AtomicBoolean sawAnotherWorker = new java.util.concurrent.atomic.AtomicBoolean();
        add(1, "starting#1", (SmartBehaviour<Tick>) e -> {
            // ordinary start-up work (waiting on class loading, a lock, I/O), shorter than the warning time: it
            // waits until the watchdog has started another worker for it, or for half the warning time
            long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WARNING_MILLIS / 2);
            while (System.nanoTime() < until && !sawAnotherWorker.get()) {
                sawAnotherWorker.set(bus.workerCount() == 2);
                try {
                    Thread.sleep(2);
                } catch (InterruptedException ie) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
            done.countDown();
        });
        bus.deliver(new Tick());
        assertThat(done.await(DEADLINE.toMillis(), TimeUnit.MILLISECONDS)).isTrue();
        assertThat(sawAnotherWorker).as("the watchdog started another worker while it was in its call").isTrue();
        await("the extra worker retires once idle").atMost(DEADLINE).until(() -> bus.workerCount() == 1);
        assertThat(log.count("warn", "has been inside one notify() call")).as("not a stall worth a warning")
                .isZero();
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
