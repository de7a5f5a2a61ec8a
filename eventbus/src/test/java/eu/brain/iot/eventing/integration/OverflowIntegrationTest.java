package eu.brain.iot.eventing.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
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
import eu.brain.iot.eventing.api.EventBusOverflowException;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/** The documented overflow policy: bounded queues, the publisher waits, then gets a clear exception. */
class OverflowIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    @InjectBundleContext
    BundleContext context;

    /** The bus's configuration, bound to any bundle ("?"); osgi-test deletes it again after the test. */
    @InjectConfiguration(withConfig = @WithConfiguration(pid = "eu.brain.iot.eventing", location = "?"))
    Configuration config;

    @Test
    void aFullQueueMakesDeliverWaitThenThrowWithoutPartialDelivery() throws Exception {
        long bus0 = busServiceId();
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("queue.capacity", 10);
        props.put("overflow.timeout.ms", 300L);
        config.update(props);
        BusTestSupport behaviours = new BusTestSupport(context);
        GatedBehaviour slow = new GatedBehaviour();
        try {
            BusTestSupport.awaitBusProperty(context, "queue.capacity", 10);
            assertThat(busServiceId()).as("the configuration is applied in place").isEqualTo(bus0);
            EventBus bus = context.getService(context.getServiceReference(EventBus.class));
            EventBusStatistics stats = context.getService(context.getServiceReference(EventBusStatistics.class));

            int baseline = stats.consumers().size();
            behaviours.typed(slow, null, PositionEvent.class);
            Recorder fast = new Recorder();
            behaviours.typed(fast, null, PositionEvent.class);
            await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers()).hasSize(baseline + 2));

            bus.deliver(new PositionEvent("robot1", 0, 0, 0));
            await().atMost(DEADLINE).until(() -> slow.received() == 1);
            for (int i = 1; i <= 10; i++) {
                bus.deliver(new PositionEvent("robot1", 0, 0, i)); // fills the slow queue to its capacity
            }
            long start = System.nanoTime();
            assertThatThrownBy(() -> bus.deliver(new PositionEvent("robot1", 0, 0, 11)))
                    .isInstanceOf(EventBusOverflowException.class)
                    .hasMessageContaining("stayed full (10 events)")
                    .hasMessageContaining(PositionEvent.class.getName());
            assertThat(Duration.ofNanos(System.nanoTime() - start)).isGreaterThanOrEqualTo(Duration.ofMillis(300));

            await().atMost(DEADLINE).until(() -> fast.events.size() == 11);
            slow.open();
            await().atMost(DEADLINE).until(() -> slow.received() == 11);
            // the refused event reached no one, not even the consumer that had room
            assertThat(fast.events).extracting(e -> ((PositionEvent) e).seq).doesNotContain(11L);

            config.delete();
            BusTestSupport.awaitBusProperty(context, "queue.capacity", 65536); // the default again, in place
            assertThat(busServiceId()).isEqualTo(bus0);
        } finally {
            slow.open(); // never leave a delivery worker blocked for the next test
        }
    }

    private long busServiceId() {
        ServiceReference<EventBus> ref = context.getServiceReference(EventBus.class);
        return ref == null ? -1 : (Long) ref.getProperty(Constants.SERVICE_ID);
    }
}
