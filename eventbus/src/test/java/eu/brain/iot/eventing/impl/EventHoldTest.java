package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;
import eu.brain.iot.eventing.spi.HeldType;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;

/** The hold for an unhandled-event policy and its hand-over to a new behaviour, on the bus core. */
class EventHoldTest {

    static final Duration DEADLINE = Duration.ofSeconds(20);

    /** Marks the events a behaviour may consume by a supertype, as the edge's behaviour consumes EdgeCommand. */
    public interface Command {
    }

    public static class Order extends BrainIoTEvent implements Command {
        public String publisher;
        public int seq;

        public Order() {
        }

        Order(String publisher, int seq) {
            this.publisher = publisher;
            this.seq = seq;
        }
    }

    public static class Other extends BrainIoTEvent {
        public int seq;
    }

    /** Holds what it is told to, counts its calls; answers at once, as the contract requires. */
    static final class Policy implements UnhandledEventPolicy {
        final Map<String, Disposition> answers = new ConcurrentHashMap<>();
        final AtomicInteger calls = new AtomicInteger();
        final List<List<String>> hierarchies = new CopyOnWriteArrayList<>();
        volatile int max = 100_000;

        @Override
        public Disposition unhandled(String eventType, List<String> typeHierarchy) {
            calls.incrementAndGet();
            if (hierarchies.size() < 10) {
                hierarchies.add(typeHierarchy);
            }
            return answers.getOrDefault(eventType, Disposition.HOLD);
        }

        @Override
        public int maxHeldEvents() {
            return max;
        }
    }

    /** Checks that each publisher's events arrive exactly once and in order, one call at a time. */
    static final class Receiver implements SmartBehaviour<Order> {
        final Map<String, List<Integer>> byPublisher = new ConcurrentHashMap<>();
        final AtomicInteger received = new AtomicInteger();

        @Override
        public void notify(Order event) {
            byPublisher.computeIfAbsent(event.publisher, p -> new ArrayList<>()).add(event.seq);
            received.incrementAndGet();
        }
    }

    final RecordingLogger log = new RecordingLogger();
    final AtomicLong ids = new AtomicLong();
    AsyncEventBus bus;

    @AfterEach
    void tearDown() {
        if (bus != null) {
            bus.close();
        }
    }

    private AsyncEventBus bus(long overflowMillis) {
        bus = new AsyncEventBus("node", 1_000, overflowMillis, new DeliveryPool.Settings(2,
                TimeUnit.MICROSECONDS.toNanos(50), TimeUnit.MILLISECONDS.toNanos(5), TimeUnit.SECONDS.toNanos(1)),
                log.logger);
        return bus;
    }

    private long add(Object behaviour, String filter, boolean untyped, String... consumed) {
        long id = ids.incrementAndGet();
        try {
            bus.addConsumer(new ConsumerSpec(id, "b#" + id, "test.bundle", Set.of(consumed),
                    filter == null ? null : FrameworkUtil.createFilter(filter), false, untyped,
                    BehaviourHandle.of(behaviour), className -> null));
        } catch (InvalidSyntaxException e) {
            throw new AssertionError(e);
        }
        return id;
    }

    private long addLastResort(UntypedSmartBehaviour behaviour) {
        long id = ids.incrementAndGet();
        bus.addConsumer(new ConsumerSpec(id, "last#" + id, "test.bundle", Set.of(), null, true, true,
                BehaviourHandle.of(behaviour), className -> null));
        return id;
    }

    private EventTypeStatistics statsOf(String type) {
        return bus.eventTypes().stream().filter(s -> s.eventType.equals(type)).findFirst()
                .orElseGet(EventTypeStatistics::new);
    }

    private static void assertExactlyOnceInOrder(Receiver receiver, int publishers, int perPublisher) {
        assertThat(receiver.byPublisher).hasSize(publishers);
        receiver.byPublisher.forEach((publisher, seqs) -> {
            assertThat(seqs).as("events of %s", publisher).hasSize(perPublisher);
            for (int i = 0; i < perPublisher; i++) {
                if (seqs.get(i) != i) {
                    throw new AssertionError(publisher + ": event " + i + " arrived as " + seqs.get(i)
                            + " (lost, duplicated or overtaken)");
                }
            }
        });
    }

    /**
     * The guarantee under concurrency: 10,000 events from 4 publishers while the behaviour that consumes them
     * is added at a different moment in each round (before the first event, during, after the last): each
     * arrives exactly once, in each publisher's order, and nothing stays held. Rounds alternate between a
     * behaviour consuming the class and one consuming its interface (the type hierarchy).
     */
    @Test
    void eventsPublishedBeforeDuringAndAfterTheHandOverArriveOnceInOrder() throws Exception {
        int publishers = 4;
        int perPublisher = 2_500;
        int total = publishers * perPublisher;
        int rounds = 24;
        for (int round = 0; round < rounds; round++) {
            bus(10_000);
            Policy policy = new Policy();
            bus.policy(policy);
            Receiver receiver = new Receiver();
            AtomicInteger published = new AtomicInteger();
            int addAfter = round * total / (rounds - 2); // from 0 to beyond the last event
            CountDownLatch start = new CountDownLatch(1);
            List<Thread> threads = new ArrayList<>();
            for (int p = 0; p < publishers; p++) {
                String name = "publisher" + p;
                threads.add(new Thread(() -> {
                    try {
                        start.await();
                    } catch (InterruptedException e) {
                        return;
                    }
                    Order order = new Order(name, 0);
                    for (int i = 0; i < perPublisher; i++) {
                        order.seq = i; // reused: the bus works on its own snapshot
                        bus.deliver(order);
                        published.incrementAndGet();
                    }
                }));
            }
            threads.forEach(Thread::start);
            start.countDown();
            String consumed = round % 2 == 0 ? Order.class.getName() : Command.class.getName();
            while (published.get() < Math.min(addAfter, total)) {
                Thread.onSpinWait();
            }
            add(receiver, null, false, consumed);
            for (Thread t : threads) {
                t.join(DEADLINE.toMillis());
            }
            await().atMost(DEADLINE).until(() -> receiver.received.get() >= total);
            assertExactlyOnceInOrder(receiver, publishers, perPublisher);
            EventTypeStatistics stats = statsOf(Order.class.getName());
            assertThat(stats.published).isEqualTo(total);
            assertThat(stats.held).isZero();
            assertThat(stats.unhandled).isZero();
            assertThat(bus.held()).isEmpty();
            bus.close();
            bus = null;
        }
    }

    @Test
    void thePolicyIsToldTheTypeHierarchyAndEventsTheNewBehaviourDoesNotTakeStayHeld() {
        bus(1_000);
        Policy policy = new Policy();
        bus.policy(policy);
        for (int i = 0; i < 3; i++) {
            bus.deliver(new Order("p1", i));
            bus.deliver(new Order("p2", i));
            Other other = new Other();
            other.seq = i;
            bus.deliver(other);
        }
        assertThat(policy.hierarchies.get(0)).containsExactly(Order.class.getName(), Command.class.getName(),
                BrainIoTEvent.class.getName(), Cloneable.class.getName(), "org.osgi.dto.DTO");
        assertThat(bus.held()).extracting(t -> t.eventType, t -> t.count)
                .containsExactly(org.assertj.core.groups.Tuple.tuple(Order.class.getName(), 6),
                        org.assertj.core.groups.Tuple.tuple(Other.class.getName(), 3));

        Receiver p1Only = new Receiver();
        add(p1Only, "(publisher=p1)", false, Order.class.getName());
        await().atMost(DEADLINE).until(() -> p1Only.received.get() == 3);
        assertThat(p1Only.byPublisher.get("p1")).containsExactly(0, 1, 2);
        // p2's events do not match the filter, Other is not consumed: both stay held, in order
        assertThat(bus.held()).extracting(t -> t.eventType, t -> t.count)
                .containsExactly(org.assertj.core.groups.Tuple.tuple(Order.class.getName(), 3),
                        org.assertj.core.groups.Tuple.tuple(Other.class.getName(), 3));
        assertThat(statsOf(Order.class.getName()).held).isEqualTo(3);
    }

    @Test
    void untypedEventsAreHeldAndHandedOverToo() {
        bus(1_000);
        bus.policy(new Policy());
        for (int i = 0; i < 5; i++) {
            bus.deliver("robot.Command", new HashMap<>(Map.of("seq", i)));
        }
        List<Object> got = new CopyOnWriteArrayList<>();
        add((UntypedSmartBehaviour) (type, data) -> got.add(data.get("seq")), null, true, "robot.Command");
        await().atMost(DEADLINE).until(() -> got.size() == 5);
        assertThat(got).containsExactly(0, 1, 2, 3, 4);
    }

    @Test
    void discardGivesUpOneTypeCountsItUnhandledAndLaterEventsGoToThePolicyAgain() {
        bus(1_000);
        Policy policy = new Policy();
        bus.policy(policy);
        for (int i = 0; i < 5; i++) {
            bus.deliver(new Order("p", i));
        }
        bus.deliver(new Other());
        assertThat(bus.discard(Order.class.getName(), "no repository has it")).isEqualTo(5);
        assertThat(statsOf(Order.class.getName()).unhandled).isEqualTo(5);
        assertThat(statsOf(Order.class.getName()).held).isZero();
        assertThat(log.count("warn", "were given up")).isEqualTo(1);
        assertThat(bus.held()).extracting(t -> t.eventType).containsExactly(Other.class.getName());
        assertThat(bus.discard(Order.class.getName(), "again")).isZero();

        int calls = policy.calls.get();
        bus.deliver(new Order("p", 5));
        assertThat(policy.calls.get()).isEqualTo(calls + 1);
        assertThat(statsOf(Order.class.getName()).held).isEqualTo(1);
    }

    @Test
    void aFullHoldMakesThePublisherWaitThenThrowAndAHandOverMakesRoom() throws Exception {
        bus(300);
        Policy policy = new Policy();
        policy.max = 3;
        bus.policy(policy);
        for (int i = 0; i < 3; i++) {
            bus.deliver(new Order("p", i));
        }
        long start = System.nanoTime();
        assertThatThrownBy(() -> bus.deliver(new Order("p", 99))).isInstanceOf(EventBusOverflowException.class)
                .hasMessageContaining(Order.class.getName()).hasMessageContaining("holds 3 events")
                .hasMessageContaining("max.held.events");
        assertThat(Duration.ofNanos(System.nanoTime() - start)).isGreaterThanOrEqualTo(Duration.ofMillis(300));
        assertThat(statsOf(Order.class.getName()).published).isEqualTo(3); // the refused one was not accepted

        bus.reconfigure(1_000, 10_000, new DeliveryPool.Settings(2, 50_000, 5_000_000, 1_000_000_000));
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread waiting = new Thread(() -> {
            try {
                bus.deliver(new Order("p", 3));
            } catch (Throwable t) {
                failure.set(t);
            }
        });
        waiting.start();
        await().atMost(DEADLINE).until(() -> waiting.getState() == Thread.State.TIMED_WAITING);
        Receiver receiver = new Receiver();
        add(receiver, null, false, Order.class.getName());
        waiting.join(DEADLINE.toMillis());
        assertThat(failure.get()).isNull();
        await().atMost(DEADLINE).until(() -> receiver.received.get() == 4);
        assertThat(receiver.byPublisher.get("p")).containsExactly(0, 1, 2, 3);
    }

    @Test
    void unhandledAnswersNeverWaitAndLastResortAnswersGoToTheConsumerOfLastResort() {
        bus(10_000);
        Policy policy = new Policy();
        policy.max = 1;
        policy.answers.put(Other.class.getName(), UnhandledEventPolicy.Disposition.UNHANDLED);
        policy.answers.put("robot.Alert", UnhandledEventPolicy.Disposition.LAST_RESORT);
        bus.policy(policy);
        bus.deliver(new Order("p", 0)); // the hold is now full
        long start = System.nanoTime();
        Other other = new Other();
        for (int i = 0; i < 100_000; i++) {
            bus.deliver(other);
        }
        assertThat(Duration.ofNanos(System.nanoTime() - start)).isLessThan(Duration.ofSeconds(10)); // never 10 s
        assertThat(statsOf(Other.class.getName()).unhandled).isEqualTo(100_000);
        assertThat(log.count("warn", "No smart behaviour consumes")).isEqualTo(1);

        List<String> lastResort = new CopyOnWriteArrayList<>();
        addLastResort((type, data) -> lastResort.add(type));
        bus.deliver("robot.Alert", new HashMap<>());
        await().atMost(DEADLINE).until(() -> lastResort.size() == 1);
        // held events are not given to a consumer of last resort while the policy holds them
        assertThat(lastResort).containsExactly("robot.Alert");
        assertThat(statsOf(Order.class.getName()).held).isEqualTo(1);
    }

    @Test
    void whenThePolicyGoesAwayHeldEventsFollowTheBusRulesInOrder() {
        bus(1_000);
        Policy first = new Policy();
        bus.policy(first);
        for (int i = 0; i < 5; i++) {
            bus.deliver(new Order("p", i));
        }
        // replaced by a higher-ranked policy first (DS binds the new one, then unbinds the old): the hold stays
        Policy second = new Policy();
        bus.policy(second);
        bus.policyGone(first);
        assertThat(statsOf(Order.class.getName()).held).isEqualTo(5);

        List<Object> lastResort = new CopyOnWriteArrayList<>();
        addLastResort((type, data) -> lastResort.add(data.get("seq")));
        bus.policyGone(second);
        await().atMost(DEADLINE).until(() -> lastResort.size() == 5);
        assertThat(lastResort).containsExactly(0, 1, 2, 3, 4);
        assertThat(statsOf(Order.class.getName()).held).isZero();

        // without a consumer of last resort they are counted as unhandled, never dropped silently
        Policy third = new Policy();
        bus.policy(third);
        bus.deliver(new Other());
        bus.deliver(new Other());
        bus.removeConsumer(ids.get());
        bus.policyGone(third);
        assertThat(statsOf(Other.class.getName()).unhandled).isEqualTo(2);
        assertThat(statsOf(Other.class.getName()).held).isZero();
    }

    @Test
    void anEventPublishedFromInsideThePolicyIsNotPutToItAgain() {
        bus(1_000);
        AtomicInteger calls = new AtomicInteger();
        bus.policy(new UnhandledEventPolicy() {
            @Override
            public Disposition unhandled(String eventType, List<String> typeHierarchy) {
                calls.incrementAndGet();
                bus.deliver(new Other()); // breaks the contract; must not recurse
                return Disposition.UNHANDLED;
            }

            @Override
            public int maxHeldEvents() {
                return 10;
            }
        });
        bus.deliver(new Order("p", 0));
        assertThat(calls.get()).isEqualTo(1);
        assertThat(statsOf(Other.class.getName()).unhandled).isEqualTo(1);
        assertThat(statsOf(Order.class.getName()).unhandled).isEqualTo(1);
        List<HeldType> held = bus.held();
        assertThat(held).isEmpty();
    }
}
