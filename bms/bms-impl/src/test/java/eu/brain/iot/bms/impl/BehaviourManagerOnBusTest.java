package eu.brain.iot.bms.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.atomic.LongAdder;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bms.api.BehaviourInstallFailed;
import eu.brain.iot.bms.api.BehaviourNotFound;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.impl.BusCore;

/**
 * The BMS core on the real bus core (its hold and hand-over), with real threads and real time; the installer is a
 * test double that registers the behaviour with the bus when the test says so, as the real one does when the
 * bundle's component activates. The same scenarios with the real installer and real bundles run in Felix in
 * itests/.
 */
class BehaviourManagerOnBusTest {

    static final Duration DEADLINE = Duration.ofSeconds(30);

    public static class Order extends BrainIoTEvent {
        public String publisher;
        public int seq;
    }

    public static class Unknown extends BrainIoTEvent {
        public int seq;
    }

    /** Checks each publisher's events: exactly once, in order. */
    static final class Receiver implements SmartBehaviour<Order> {
        final Map<String, List<Integer>> byPublisher = new ConcurrentHashMap<>();
        final AtomicInteger received = new AtomicInteger();

        @Override
        public void notify(Order event) {
            byPublisher.computeIfAbsent(event.publisher, p -> new ArrayList<>()).add(event.seq);
            received.incrementAndGet();
        }
    }

    static final class AlertReceiver<T extends BrainIoTEvent> implements SmartBehaviour<T> {
        final List<T> alerts = new CopyOnWriteArrayList<>();

        @Override
        public void notify(T event) {
            alerts.add(event);
        }
    }

    private final RecordingLogger log = new RecordingLogger();
    private final FakeInstaller installer = new FakeInstaller();
    private final ManagerCountersImpl counters = new ManagerCountersImpl();
    private BusCore bus;
    private ThreadScheduler scheduler;
    private BehaviourManager bms;

    @BeforeEach
    void start() {
        installer.offer(Order.class.getName(), "test.order.behaviour", "1.0.0");
    }

    private void startBms(Settings settings) {
        bus = new BusCore(65_536, 5_000, log.logger);
        scheduler = new ThreadScheduler("brain-iot-bms", log.logger);
        bms = new BehaviourManager(installer, bus, scheduler, new Alerts(bus, Runnable::run, log.logger,
                new LongAdder()), log.logger, counters, settings, () -> false);
        bms.start();
        bus.policy(new eu.brain.iot.eventing.spi.UnhandledEventPolicy() {
            @Override
            public Disposition unhandled(String eventType, List<String> typeHierarchy) {
                return bms.unhandled(eventType, typeHierarchy, Map::of);
            }

            @Override
            public Disposition unhandled(String eventType, List<String> typeHierarchy,
                    java.util.function.Supplier<Map<String, Object>> fields) {
                return bms.unhandled(eventType, typeHierarchy, fields);
            }

            @Override
            public int maxHeldEvents() {
                return bms.maxHeldEvents();
            }
        });
    }

    @AfterEach
    void stop() {
        if (scheduler != null) {
            scheduler.close();
        }
        if (bus != null) {
            bus.close();
        }
    }

    @Test
    void aBurstFromFourPublishersDuringTheInstallIsDeliveredExactlyOnceInOrder() throws Exception {
        startBms(Settings.DEFAULTS);
        int publishers = 4;
        int perPublisher = 2_500;
        AtomicInteger published = new AtomicInteger();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        CountDownLatch go = new CountDownLatch(1);
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < publishers; p++) {
            String name = "publisher-" + p;
            Thread t = new Thread(() -> {
                try {
                    go.await();
                    for (int i = 0; i < perPublisher; i++) {
                        Order o = new Order();
                        o.publisher = name;
                        o.seq = i;
                        bus.deliver(o);
                        published.incrementAndGet();
                    }
                } catch (Throwable e) {
                    failure.set(e);
                }
            }, name);
            t.start();
            threads.add(t);
        }
        go.countDown();
        await().atMost(DEADLINE).until(() -> !installer.requests.isEmpty());
        await().atMost(DEADLINE).until(() -> published.get() >= publishers * perPublisher / 4);
        // the installer's bundle starts while the publishers go on: the bus hands the held events over as the
        // behaviour registers, then the install's promise resolves
        Receiver receiver = new Receiver();
        bus.addBehaviour(receiver, Order.class.getName());
        installer.last().succeed();
        for (Thread t : threads) {
            t.join();
        }
        assertThat(failure.get()).isNull();

        await().atMost(DEADLINE).until(() -> receiver.received.get() >= publishers * perPublisher);
        assertThat(receiver.byPublisher).hasSize(publishers);
        receiver.byPublisher.forEach((publisher, seqs) -> {
            assertThat(seqs).as(publisher).hasSize(perPublisher);
            for (int i = 0; i < perPublisher; i++) {
                assertThat(seqs.get(i)).as("%s's event %d", publisher, i).isEqualTo(i);
            }
        });
        assertThat(installer.requests).hasSize(1);
        assertThat(counters.snapshot().heldEvents).isPositive(); // some events did wait in the hold
        assertThat(bus.statistics(Order.class.getName()).unhandled).isZero();
        assertThat(bus.held()).isEmpty();
    }

    @Test
    void theSearchIsGivenTheFieldsOfTheEpisodesFirstEvent() {
        startBms(Settings.DEFAULTS);
        for (int seq = 7; seq <= 9; seq++) {
            Order o = new Order();
            o.publisher = "robot" + seq; // a device the event names: a fabric's installer may choose its owner
            o.seq = seq;
            bus.deliver(o);
        }
        await().atMost(DEADLINE).until(() -> !installer.findEvents.isEmpty());
        assertThat(installer.findEvents).singleElement().satisfies(event -> {
            assertThat(event.get("publisher")).isEqualTo("robot7");
            assertThat(event.get("seq")).isEqualTo(7);
        });
    }

    @Test
    void aPublisherOfATypeNoRepositoryHasNeverWaitsAndOneAlertSaysSo() {
        startBms(Settings.DEFAULTS);
        AlertReceiver<BehaviourNotFound> alerts = new AlertReceiver<>();
        bus.addBehaviour(alerts, BehaviourNotFound.class.getName());
        for (int i = 0; i < 100_000; i++) {
            Unknown u = new Unknown();
            u.seq = i;
            bus.deliver(u);
            assertThat(bus.held()).as("nothing is ever held").isEmpty();
        }
        await().atMost(DEADLINE).until(() -> !alerts.alerts.isEmpty());
        assertThat(alerts.alerts).singleElement().extracting(a -> a.eventType).isEqualTo(Unknown.class.getName());
        assertThat(bus.statistics(Unknown.class.getName()).unhandled).isEqualTo(100_000);
        assertThat(counters.snapshot().heldEvents).isZero();
        assertThat(installer.finds).hasValue(1);
    }

    @Test
    void heldEventsAreKeptWhileInstallsFailThenDiscardedAndCountedAtTheDeadline() {
        startBms(new Settings(1_000, 60_000, 20, 40, 400, 1_000, 50, List.of(), 16, 1_000));
        AlertReceiver<BehaviourInstallFailed> alerts = new AlertReceiver<>();
        bus.addBehaviour(alerts, BehaviourInstallFailed.class.getName());
        // every attempt fails, as with a repository that cannot be reached
        installer.failEveryInstall = new InstallException(Problem.DOWNLOAD_FAILED,
                "http://127.0.0.1:1/order.jar: connection refused");
        for (int i = 0; i < 10; i++) {
            Order o = new Order();
            o.publisher = "p";
            o.seq = i;
            bus.deliver(o);
        }
        await().atMost(DEADLINE).until(() -> alerts.alerts.stream().anyMatch(a -> a.finalFailure));
        assertThat(installer.requests.size()).isGreaterThan(1); // retried
        assertThat(bus.held()).isEmpty();
        assertThat(bus.statistics(Order.class.getName()).unhandled).isEqualTo(10);
        assertThat(counters.snapshot().discardedEvents).isEqualTo(10);
        BehaviourInstallFailed last = alerts.alerts.get(alerts.alerts.size() - 1);
        assertThat(last.problem).isEqualTo("DOWNLOAD_FAILED");
        assertThat(last.heldEvents).isEqualTo(10);
    }
}
