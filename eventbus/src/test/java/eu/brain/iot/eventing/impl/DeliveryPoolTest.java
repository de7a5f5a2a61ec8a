package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/** The delivery pool through the bus core: order, exclusion, isolation by the stall watchdog, retiring. */
class DeliveryPoolTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    public static class Tick extends BrainIoTEvent {
        public String publisher;
        public long seq;

        Tick() {
        }

        Tick(String publisher, long seq) {
            this.publisher = publisher;
            this.seq = seq;
        }
    }

    /** Blocks in notify() until opened (or interrupted); counts what it got. */
    static final class Gate implements SmartBehaviour<Tick> {
        final CountDownLatch open = new CountDownLatch(1);
        final AtomicInteger received = new AtomicInteger();
        final AtomicInteger interrupted = new AtomicInteger();

        @Override
        public void notify(Tick event) {
            received.incrementAndGet();
            try {
                open.await();
            } catch (InterruptedException e) {
                interrupted.incrementAndGet();
            }
        }
    }

    static final class Counter implements SmartBehaviour<Tick> {
        final AtomicInteger received = new AtomicInteger();

        @Override
        public void notify(Tick event) {
            received.incrementAndGet();
        }
    }

    final RecordingLogger log = new RecordingLogger();
    final AtomicLong ids = new AtomicLong();
    final List<Gate> gates = new ArrayList<>();
    AsyncEventBus bus;

    @AfterEach
    void tearDown() {
        gates.forEach(g -> g.open.countDown());
        if (bus != null) {
            bus.close();
        }
    }

    private AsyncEventBus bus(int workers, long keepAliveMillis) {
        bus = new AsyncEventBus("node", 10_000, 10_000, new DeliveryPool.Settings(workers,
                TimeUnit.MICROSECONDS.toNanos(50), TimeUnit.MILLISECONDS.toNanos(5),
                TimeUnit.MILLISECONDS.toNanos(keepAliveMillis)), log.logger);
        return bus;
    }

    private long add(String name, SmartBehaviour<Tick> behaviour) {
        return add(name, BehaviourHandle.of(behaviour));
    }

    private long add(String name, BehaviourHandle handle) {
        long id = ids.incrementAndGet();
        bus.addConsumer(new ConsumerSpec(id, name + "#" + id, "test.bundle", Set.of(Tick.class.getName()), null,
                false, false, handle, className -> null));
        return id;
    }

    private Gate gate() {
        Gate gate = new Gate();
        gates.add(gate);
        return gate;
    }

    private static List<String> busThreadNames() {
        return Thread.getAllStackTraces().keySet().stream().filter(Thread::isAlive).map(Thread::getName)
                .filter(n -> n.startsWith("brain-iot-bus")).toList();
    }

    private EventTypeStatistics tickStatistics() {
        return bus.eventTypes().stream().filter(s -> s.eventType.equals(Tick.class.getName())).findFirst()
                .orElseThrow();
    }

    @Test
    void everyBehaviourSeesEachPublishersEventsInOrderOneCallAtATime() throws Exception {
        bus(2, 1_000);
        int publishers = 3;
        int perPublisher = 20_000;
        List<OrderChecker> checkers = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            OrderChecker checker = new OrderChecker();
            checkers.add(checker);
            add("checker", checker);
        }
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < publishers; p++) {
            String name = "publisher" + p;
            threads.add(new Thread(() -> {
                Tick tick = new Tick(name, 0);
                for (int i = 0; i < perPublisher; i++) {
                    tick.seq = i; // reused: the bus works on its own snapshot
                    bus.deliver(tick);
                }
            }));
        }
        threads.forEach(Thread::start);
        for (Thread t : threads) {
            t.join();
        }

        await().atMost(DEADLINE).until(() -> checkers.stream().allMatch(c -> c.received.get() == publishers * perPublisher));
        assertThat(checkers).allSatisfy(c -> {
            assertThat(c.overlaps).hasValue(0);
            assertThat(c.outOfOrder).hasValue(0);
            assertThat(c.threads).allMatch(t -> t.getName().startsWith("brain-iot-bus"));
        });
        // the behaviours share the workers rather than having a thread each
        Set<Thread> used = ConcurrentHashMap.newKeySet();
        checkers.forEach(c -> used.addAll(c.threads));
        assertThat(used.size()).isLessThan(checkers.size());
    }

    /** Checks order per publisher and that it is never called by two threads at once. */
    static final class OrderChecker implements SmartBehaviour<Tick> {
        /** Touched only inside notify(): safe exactly when the bus keeps its promise of one call at a time. */
        final Map<String, Long> last = new HashMap<>();
        final AtomicInteger inside = new AtomicInteger();
        final AtomicInteger overlaps = new AtomicInteger();
        final AtomicInteger outOfOrder = new AtomicInteger();
        final AtomicInteger received = new AtomicInteger();
        final Set<Thread> threads = ConcurrentHashMap.newKeySet();

        @Override
        public void notify(Tick event) {
            if (inside.incrementAndGet() != 1) {
                overlaps.incrementAndGet();
            }
            Long previous = last.put(event.publisher, event.seq);
            if (previous == null ? event.seq != 0 : previous + 1 != event.seq) {
                outOfOrder.incrementAndGet();
            }
            threads.add(Thread.currentThread());
            inside.decrementAndGet();
            received.incrementAndGet();
        }
    }

    @Test
    void aBlockedBehaviourDoesNotStopTheOthersEvenWithOneWorker() {
        bus(1, 60_000);
        Gate blocked = gate();
        add("blocked", blocked);
        Counter fast = new Counter();
        add("fast", fast);

        for (int i = 0; i < 1_000; i++) {
            bus.deliver(new Tick("p", i));
        }

        // the only worker is stuck in the blocked behaviour: the watchdog added one for the others
        await().atMost(DEADLINE).until(() -> fast.received.get() == 1_000);
        assertThat(blocked.received).hasValue(1);
        assertThat(bus.workerCount()).isGreaterThanOrEqualTo(2);
        assertThat(busThreadNames()).anyMatch(n -> n.startsWith("brain-iot-bus[blocked#"));
        await("the stall logged once it lasted the warning time").atMost(DEADLINE)
                .until(() -> log.count("warn", "inside one notify() call") == 1);

        blocked.open.countDown();
        await().atMost(DEADLINE).until(() -> blocked.received.get() == 1_000);
        await().atMost(DEADLINE).until(() -> busThreadNames().stream().noneMatch(n -> n.startsWith("brain-iot-bus[")));
    }

    @Test
    void aBehaviourComputingForLongDoesNotStopTheOthers() {
        bus(1, 60_000);
        AtomicBoolean done = new AtomicBoolean();
        add("computing", e -> {
            while (!done.get()) {
                Thread.onSpinWait(); // burns CPU, as a long computation would
            }
        });
        Counter fast = new Counter();
        add("fast", fast);
        try {
            for (int i = 0; i < 100; i++) {
                bus.deliver(new Tick("p", i));
            }
            await().atMost(DEADLINE).until(() -> fast.received.get() == 100);
            assertThat(bus.workerCount()).isGreaterThanOrEqualTo(2);
        } finally {
            done.set(true);
        }
    }

    @Test
    void aBehaviourBlockedInIoDoesNotStopTheOthers() throws Exception {
        bus(1, 60_000);
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            add("accepting", e -> {
                try {
                    server.accept().close(); // blocks in native code: Java reports the thread as running
                } catch (IOException closed) {
                    // the test is over
                }
            });
            Counter fast = new Counter();
            add("fast", fast);
            for (int i = 0; i < 100; i++) {
                bus.deliver(new Tick("p", i));
            }
            await().atMost(DEADLINE).until(() -> fast.received.get() == 100);
            assertThat(bus.workerCount()).isGreaterThanOrEqualTo(2);
        }
    }

    @Test
    void workersAddedForBlockedBehavioursRetireOnceIdle() {
        bus(1, 50);
        List<Gate> blocked = List.of(gate(), gate(), gate());
        blocked.forEach(g -> add("blocked", g));
        Counter fast = new Counter();
        add("fast", fast);

        for (int i = 0; i < 100; i++) {
            bus.deliver(new Tick("p", i));
        }
        // no bound: each blocked behaviour holds one worker, and one more serves the others
        await().atMost(DEADLINE).until(() -> fast.received.get() == 100);
        assertThat(bus.workerCount()).isGreaterThanOrEqualTo(4);

        blocked.forEach(g -> g.open.countDown());
        await().atMost(DEADLINE).until(() -> blocked.stream().allMatch(g -> g.received.get() == 100));
        await().atMost(DEADLINE).until(() -> bus.workerCount() == 1);
        await().atMost(DEADLINE).until(() -> busThreadNames().stream()
                .filter(n -> n.startsWith(DeliveryWorker.NAME_PREFIX)).count() == 1);
    }

    @Test
    void removingABlockedBehaviourInterruptsItDiscardsItsQueueAndReleasesItOnAWorker() {
        bus(2, 1_000);
        Gate blocked = gate();
        RecordingHandle handle = new RecordingHandle(blocked);
        long id = add("leaving", handle);
        bus.deliver(new Tick("p", 0));
        await().atMost(DEADLINE).until(() -> blocked.received.get() == 1);
        for (int i = 1; i <= 10; i++) {
            bus.deliver(new Tick("p", i));
        }

        bus.removeConsumer(id);

        await().atMost(DEADLINE).until(() -> handle.releases.get() == 1);
        assertThat(blocked.interrupted).hasValue(1);
        assertThat(tickStatistics().discarded).isEqualTo(10);
        assertThat(tickStatistics().failed).isZero();
        assertThat(handle.threads).allMatch(n -> n.startsWith("brain-iot-bus"));
        // later events for it are counted as unhandled, not queued anywhere
        bus.deliver(new Tick("p", 11));
        assertThat(tickStatistics().unhandled).isEqualTo(1);
    }

    /** Records the threads that fetch and give back the behaviour object. */
    static final class RecordingHandle implements BehaviourHandle {
        final Object behaviour;
        final AtomicInteger releases = new AtomicInteger();
        final Set<String> threads = ConcurrentHashMap.newKeySet();

        RecordingHandle(Object behaviour) {
            this.behaviour = behaviour;
        }

        @Override
        public Object get() {
            threads.add(Thread.currentThread().getName());
            return behaviour;
        }

        @Override
        public void release() {
            threads.add(Thread.currentThread().getName());
            releases.incrementAndGet();
        }
    }

    @Test
    void anInterruptLeftByOneBehaviourDoesNotReachTheNext() {
        bus(1, 1_000);
        add("self-interrupting", e -> Thread.currentThread().interrupt());
        AtomicInteger sawInterrupt = new AtomicInteger();
        Counter next = new Counter();
        add("next", e -> {
            if (Thread.currentThread().isInterrupted()) {
                sawInterrupt.incrementAndGet();
            }
            next.notify(e);
        });

        for (int i = 0; i < 500; i++) {
            bus.deliver(new Tick("p", i));
        }
        await().atMost(DEADLINE).until(() -> next.received.get() == 500);
        assertThat(sawInterrupt).hasValue(0);
    }

    @Test
    void aThrowingBehaviourIsCountedAndKeepsItsTurns() {
        bus(1, 1_000);
        AtomicInteger calls = new AtomicInteger();
        add("throwing", e -> {
            calls.incrementAndGet();
            throw new IllegalStateException("bug");
        });
        Counter healthy = new Counter();
        add("healthy", healthy);

        for (int i = 0; i < 300; i++) {
            bus.deliver(new Tick("p", i));
        }
        await().atMost(DEADLINE).until(() -> calls.get() == 300 && healthy.received.get() == 300);
        await().atMost(DEADLINE).until(() -> tickStatistics().failed == 300);
        assertThat(log.count("error", "failed on an event")).isEqualTo(1);
    }

    @Test
    void eventsArrivingAfterTheWorkersParkedWakeThem() {
        bus(2, 60_000);
        List<Counter> counters = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            Counter counter = new Counter();
            counters.add(counter);
            add("paced", counter);
        }
        for (int i = 1; i <= 10; i++) {
            bus.deliver(new Tick("p", i));
            int expected = i;
            // Awaitility's first check comes after 100 ms: the workers have parked long before
            await().atMost(DEADLINE).until(() -> counters.stream().allMatch(c -> c.received.get() == expected));
        }
    }

    @Test
    void closingTheBusEndsEveryBusThread() {
        bus(2, 1_000);
        Counter counter = new Counter();
        add("any", counter);
        bus.deliver(new Tick("p", 0));
        await().atMost(DEADLINE).until(() -> counter.received.get() == 1);

        bus.close();
        bus = null;

        await().atMost(DEADLINE).until(() -> busThreadNames().isEmpty());
    }

    @Test
    void closingTheBusGivesEveryBehaviourBackEvenWithOneWorker() {
        // Closing queues a last turn per behaviour, then stops the pool: a worker woken for those turns must not end
        // before it served them. Many rounds, because the worker may be spinning, parking or parked at that moment.
        // (The race fixed in DeliveryPool.awaitReady, a worker reading "stopped" just after an empty poll, is only
        // nanoseconds wide: these rounds did not hit it with the old code either; they guard the close path.)
        for (int round = 0; round < 200; round++) {
            bus(1, 60_000);
            List<RecordingHandle> handles = new ArrayList<>();
            List<Counter> counters = new ArrayList<>();
            for (int i = 0; i < 8; i++) {
                Counter counter = new Counter();
                RecordingHandle handle = new RecordingHandle(counter);
                counters.add(counter);
                handles.add(handle);
                add("b" + i, handle);
            }
            bus.deliver(new Tick("p", round));
            await().pollDelay(Duration.ZERO).pollInterval(Duration.ofMillis(1)).atMost(DEADLINE)
                    .until(() -> counters.stream().allMatch(c -> c.received.get() == 1));

            bus.close();
            bus = null;

            int r = round;
            await("round " + r + ": every behaviour object given back").pollDelay(Duration.ZERO)
                    .pollInterval(Duration.ofMillis(1)).atMost(DEADLINE)
                    .until(() -> handles.stream().allMatch(h -> h.releases.get() == 1));
        }
        await().atMost(DEADLINE).until(() -> busThreadNames().isEmpty());
    }
}
