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
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * The documented overflow policy: bounded queues; a publisher waits for a full queue, and a behaviour stalled for the
 * overflow timeout stops taking events so that the other behaviours of the type keep theirs.
 */
class OverflowIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    @InjectBundleContext
    BundleContext context;

    /** The bus's configuration, bound to any bundle ("?"); osgi-test deletes it again after the test. */
    @InjectConfiguration(withConfig = @WithConfiguration(pid = "eu.brain.iot.eventing", location = "?"))
    Configuration config;

    @Test
    void aStalledBehaviourStopsTakingEventsSoThatTheOthersKeepTheirsAndResumesWhenNotifyReturns() throws Exception {
        long bus0 = busServiceId();
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("queue.capacity", 10);
        props.put("overflow.timeout.ms", 300L);
        config.update(props);
        BusTestSupport behaviours = new BusTestSupport(context);
        GatedBehaviour stuck = new GatedBehaviour();
        try {
            BusTestSupport.awaitBusProperty(context, "queue.capacity", 10);
            assertThat(busServiceId()).as("the configuration is applied in place").isEqualTo(bus0);
            EventBus bus = context.getService(context.getServiceReference(EventBus.class));
            EventBusStatistics stats = context.getService(context.getServiceReference(EventBusStatistics.class));

            int baseline = stats.consumers().size();
            long stuckId = (Long) behaviours.typed(stuck, null, PositionEvent.class).getReference()
                    .getProperty(Constants.SERVICE_ID);
            Recorder healthy = new Recorder();
            behaviours.typed(healthy, null, PositionEvent.class);
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers()).hasSize(baseline + 2));

            bus.deliver(new PositionEvent("robot1", 0, 0, 0));
            await().atMost(DEADLINE).until(() -> stuck.received() == 1);
            for (int i = 1; i <= 10; i++) {
                bus.deliver(new PositionEvent("robot1", 0, 0, i)); // fills the stuck queue to its capacity
            }
            long start = System.nanoTime();
            for (int i = 11; i <= 50; i++) {
                bus.deliver(new PositionEvent("robot1", 0, 0, i)); // neither throws nor waits for ever
            }
            assertThat(Duration.ofNanos(System.nanoTime() - start)).as("it was waited for once, the overflow timeout")
                    .isGreaterThanOrEqualTo(Duration.ofMillis(300));
            await().atMost(DEADLINE).until(() -> healthy.events.size() == 51);

            ConsumerStatistics stalled = consumer(stats, stuckId);
            assertThat(stalled.stalled).as("bus:behaviours shows it stalled").isTrue();
            assertThat(stalled.discarded).isEqualTo(40);
            assertThat(stats.eventTypes()).filteredOn(t -> t.eventType.equals(PositionEvent.class.getName()))
                    .singleElement().satisfies(t -> assertThat(t.discarded).isEqualTo(40));

            stuck.open();
            await().atMost(DEADLINE).until(() -> stuck.received() == 11);
            await().atMost(DEADLINE).until(() -> !consumer(stats, stuckId).stalled);
            bus.deliver(new PositionEvent("robot1", 0, 0, 51));
            await().atMost(DEADLINE).until(() -> stuck.received() == 12);

            config.delete();
            BusTestSupport.awaitBusProperty(context, "queue.capacity", 65536); // the default again, in place
            assertThat(busServiceId()).isEqualTo(bus0);
        } finally {
            stuck.open(); // never leave a delivery worker blocked for the next test
        }
    }

    private static ConsumerStatistics consumer(EventBusStatistics stats, long serviceId) {
        return stats.consumers().stream().filter(c -> c.serviceId == serviceId).findFirst().orElseThrow();
    }

    private long busServiceId() {
        ServiceReference<EventBus> ref = context.getServiceReference(EventBus.class);
        return ref == null ? -1 : (Long) ref.getProperty(Constants.SERVICE_ID);
    }
}
