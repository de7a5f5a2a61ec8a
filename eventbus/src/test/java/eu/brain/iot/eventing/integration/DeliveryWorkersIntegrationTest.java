package eu.brain.iot.eventing.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.Hashtable;

import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.Configuration;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;
import org.osgi.test.common.annotation.config.InjectConfiguration;
import org.osgi.test.common.annotation.config.WithConfiguration;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * Isolation on a shared worker pool, configured through Config Admin: even with a single delivery worker, a
 * blocked behaviour delays nobody, because the stall watchdog adds a worker; that worker retires afterwards.
 */
class DeliveryWorkersIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);
    static final String WORKER = "brain-iot-bus-worker-";

    @InjectBundleContext
    BundleContext context;

    /** The bus's configuration, bound to any bundle ("?"); osgi-test deletes it again after the test. */
    @InjectConfiguration(withConfig = @WithConfiguration(pid = "eu.brain.iot.eventing", location = "?"))
    Configuration config;

    @Test
    void withOneDeliveryWorkerABlockedBehaviourStillDelaysNobody() throws Exception {
        long bus0 = busServiceId();
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("delivery.workers", 1);
        props.put("stall.threshold.ms", 5L);
        config.update(props);
        BusTestSupport behaviours = new BusTestSupport(context);
        GatedBehaviour blocked = new GatedBehaviour();
        try {
            BusTestSupport.awaitBusProperty(context, "delivery.workers", 1);
            assertThat(busServiceId()).as("the configuration is applied in place").isEqualTo(bus0);
            EventBus bus = context.getService(context.getServiceReference(EventBus.class)); // activates it
            EventBusStatistics stats = context.getService(context.getServiceReference(EventBusStatistics.class));
            // the surplus workers retire once idle: the configured single worker remains
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(workerThreads()).hasSize(1));

            int baseline = stats.consumers().size();
            behaviours.typed(blocked, null, PositionEvent.class);
            Recorder fast = new Recorder();
            behaviours.typed(fast, null, PositionEvent.class);
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers()).hasSize(baseline + 2));

            for (int i = 0; i < 1_000; i++) {
                bus.deliver(new PositionEvent("r1", i, 0, i));
            }
            await().atMost(DEADLINE).until(() -> fast.events.size() == 1_000);
            assertThat(blocked.received()).isEqualTo(1);
            assertThat(fast.threads).allMatch(t -> t.getName().startsWith("brain-iot-bus"));
            // a thread dump names the behaviour that holds the stalled worker
            assertThat(threadNames()).anyMatch(n -> n.startsWith("brain-iot-bus[") && n.contains("stalled"));

            blocked.open();
            await().atMost(DEADLINE).until(() -> blocked.received() == 1_000);
            // the worker added for the stall retires once idle (after a second)
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(workerThreads()).hasSize(1));
            assertThat(threadNames()).noneMatch(n -> n.startsWith("brain-iot-bus["));

            config.delete();
            BusTestSupport.awaitBusProperty(context, "delivery.workers", 0); // the default again, in place
            assertThat(busServiceId()).isEqualTo(bus0);
        } finally {
            blocked.open(); // never leave a delivery worker blocked for the next test
        }
    }

    private static java.util.List<String> threadNames() {
        return Thread.getAllStackTraces().keySet().stream().filter(Thread::isAlive).map(Thread::getName).toList();
    }

    private static java.util.List<String> workerThreads() {
        return threadNames().stream().filter(n -> n.startsWith(WORKER) || n.startsWith("brain-iot-bus[")).toList();
    }

    private long busServiceId() {
        ServiceReference<EventBus> ref = context.getServiceReference(EventBus.class);
        return ref == null ? -1 : (Long) ref.getProperty(Constants.SERVICE_ID);
    }
}
