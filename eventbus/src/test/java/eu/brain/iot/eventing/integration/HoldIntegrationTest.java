package eu.brain.iot.eventing.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectBundleInstaller;
import org.osgi.test.common.annotation.InjectService;
import org.osgi.test.common.install.BundleInstaller;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.integration.tb.HoldConsumerActivator;
import eu.brain.iot.eventing.integration.tb.HoldEvent;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;
import eu.brain.iot.eventing.spi.HeldEvents;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;

/**
 * The bus's hold with a real policy service: a behaviour bundle installed while 4 publishers send 10,000 events
 * it consumes receives each exactly once, in each publisher's order, whether the event was published before the
 * bundle was installed (held, then handed over), while it started, or after. The behaviour bundle is the jar made
 * from src/test/bundles/tb.held.consumer.bnd, embedded in the test bundle; what the test registers and installs goes
 * through osgi-test's closeable context and installer, which undo it when the test ends.
 */
class HoldIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(30);

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 5000)
    EventBus bus;

    @InjectService(timeout = 5000)
    EventBusStatistics stats;

    @InjectService(timeout = 5000)
    HeldEvents heldEvents;

    @InjectBundleInstaller
    BundleInstaller bundles;

    /** Holds {@link HoldEvent}s; everything else follows the bus's own rules. Answers at once. */
    static final class HoldPolicy implements UnhandledEventPolicy {
        final AtomicInteger asked = new AtomicInteger();

        @Override
        public Disposition unhandled(String eventType, List<String> typeHierarchy) {
            asked.incrementAndGet();
            return eventType.equals(HoldEvent.class.getName()) ? Disposition.HOLD : Disposition.LAST_RESORT;
        }

        @Override
        public int maxHeldEvents() {
            return 20_000;
        }
    }

    private static HoldEvent event(String publisher, int seq) {
        HoldEvent e = new HoldEvent();
        e.publisher = publisher;
        e.seq = seq;
        return e;
    }

    @Test
    void aBehaviourInstalledWhilePublishersRunGetsEveryHeldAndNewEventOnceInOrder() throws Exception {
        Recorder acks = new Recorder();
        BusTestSupport behaviours = new BusTestSupport(context);
        behaviours.untyped(acks, HoldConsumerActivator.ACK);
        HoldPolicy policy = new HoldPolicy();
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(Constants.SERVICE_RANKING, 10);
        context.registerService(UnhandledEventPolicy.class, policy, props);
        // the bus follows the policy once it asks it (binding is asynchronous to this thread in general)
        await().atMost(DEADLINE).until(() -> {
            bus.deliver(event("probe", 0));
            return policy.asked.get() > 0;
        });
        assertThat(heldEvents.held()).extracting(t -> t.eventType).containsExactly(HoldEvent.class.getName());

        int publishers = 4;
        int perPublisher = 2_500;
        AtomicInteger published = new AtomicInteger();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        CountDownLatch start = new CountDownLatch(1);
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < publishers; p++) {
            String name = "p" + p;
            threads.add(new Thread(() -> {
                try {
                    start.await();
                    HoldEvent e = event(name, 0);
                    for (int i = 0; i < perPublisher; i++) {
                        e.seq = i;
                        bus.deliver(e);
                        published.incrementAndGet();
                    }
                } catch (Throwable t) {
                    failure.set(t);
                }
            }, "publisher-" + name));
        }
        threads.forEach(Thread::start);
        start.countDown();
        await().atMost(DEADLINE).until(() -> published.get() >= 2_000);
        assertThat(heldEvents.held().get(0).count).as("events held before the install").isGreaterThanOrEqualTo(2_000);
        bundles.installBundle("tb.held.consumer.jar", true);
        for (Thread t : threads) {
            t.join(DEADLINE.toMillis());
        }
        assertThat(failure.get()).isNull();

        await().atMost(DEADLINE).until(() -> acks.maps.stream()
                .filter(a -> !"probe".equals(a.get("publisher"))).count() == publishers * perPublisher);
        Map<String, List<Integer>> byPublisher = new HashMap<>();
        for (Map<String, Object> ack : acks.maps) {
            assertThat(ack).containsEntry("ownClass", true);
            byPublisher.computeIfAbsent((String) ack.get("publisher"), k -> new ArrayList<>())
                    .add((Integer) ack.get("seq"));
        }
        for (int p = 0; p < publishers; p++) {
            List<Integer> seqs = byPublisher.get("p" + p);
            assertThat(seqs).as("events of p%d", p).hasSize(perPublisher);
            for (int i = 0; i < perPublisher; i++) {
                assertThat(seqs.get(i)).as("event %d of p%d (lost, duplicated or overtaken otherwise)", i, p)
                        .isEqualTo(i);
            }
        }
        assertThat(byPublisher.get("probe")).as("the probe that was held").contains(0);
        assertThat(heldEvents.held()).isEmpty();
        EventTypeStatistics held = stats.eventTypes().stream()
                .filter(s -> s.eventType.equals(HoldEvent.class.getName())).findFirst().orElseThrow();
        assertThat(held.held).isZero();
        assertThat(held.delivered).isEqualTo(held.published - held.unhandled);
    }

    @Test
    void discardGivesUpHeldEventsAndCountsThem() throws Exception {
        HoldPolicy policy = new HoldPolicy();
        context.registerService(UnhandledEventPolicy.class, policy, new Hashtable<>());
        await().atMost(DEADLINE).until(() -> {
            bus.deliver(event("d", 0));
            return !heldEvents.held().isEmpty();
        });
        long unhandledBefore = unhandled();
        int count = heldEvents.held().get(0).count;
        assertThat(heldEvents.discard(HoldEvent.class.getName(), "test: no behaviour will come")).isEqualTo(count);
        assertThat(heldEvents.held()).isEmpty();
        assertThat(unhandled() - unhandledBefore).isEqualTo(count);
    }

    private long unhandled() {
        return stats.eventTypes().stream().filter(s -> s.eventType.equals(HoldEvent.class.getName()))
                .mapToLong(s -> s.unhandled).sum();
    }
}
