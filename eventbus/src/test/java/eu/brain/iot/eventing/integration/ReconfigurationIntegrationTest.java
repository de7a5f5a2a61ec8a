package eu.brain.iot.eventing.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.lang.reflect.Method;
import java.time.Duration;
import java.util.Hashtable;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.Configuration;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectInstalledBundle;
import org.osgi.test.common.annotation.InjectService;
import org.osgi.test.common.annotation.config.InjectConfiguration;
import org.osgi.test.common.annotation.config.WithConfiguration;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.integration.tb.CopyConsumerActivator;
import eu.brain.iot.eventing.integration.tb.CopyEvent;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/** The bus's configuration applies in place, and the Gogo command that publishes an event by hand. */
class ReconfigurationIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    @InjectBundleContext
    BundleContext context;

    /** The bus's configuration, bound to any bundle ("?"); osgi-test deletes it again after the test. */
    @InjectConfiguration(withConfig = @WithConfiguration(pid = "eu.brain.iot.eventing", location = "?"))
    Configuration config;

    @InjectService(timeout = 5000)
    EventBus bus;

    @InjectService(timeout = 5000)
    EventBusStatistics stats;

    @Test
    void aReconfigurationWhileEventsAreQueuedBehindABlockedBehaviourLosesNone() throws Exception {
        long busId = busServiceId();
        BusTestSupport behaviours = new BusTestSupport(context);
        GatedBehaviour blocked = new GatedBehaviour();
        try {
            behaviours.typed(blocked, "(robotId=reconfigured)", PositionEvent.class);
            await().atMost(DEADLINE).until(() -> queueOf(blocked) != null);
            bus.deliver(new PositionEvent("reconfigured", 0, 0, 0));
            await().atMost(DEADLINE).until(() -> blocked.received() == 1);
            for (int i = 1; i <= 500; i++) {
                bus.deliver(new PositionEvent("reconfigured", 0, 0, i));
            }
            EventTypeStatistics before = statsOf(PositionEvent.class.getName());

            Hashtable<String, Object> props = new Hashtable<>();
            props.put("queue.capacity", 1_000);
            props.put("overflow.timeout.ms", 1_000L);
            props.put("delivery.workers", 3);
            props.put("stall.threshold.ms", 10L);
            props.put("idle.spin.us", 100L);
            config.update(props);
            BusTestSupport.awaitBusProperty(context, "delivery.workers", 3);
            assertThat(busServiceId()).as("the same bus, reconfigured in place").isEqualTo(busId);
            assertThat(queueOf(blocked).queueDepth).as("events still queued").isEqualTo(500);

            blocked.open();
            await().atMost(DEADLINE).until(() -> blocked.received() == 501);
            EventTypeStatistics after = statsOf(PositionEvent.class.getName());
            assertThat(after.discarded).isEqualTo(before.discarded);

            config.delete();
            BusTestSupport.awaitBusProperty(context, "delivery.workers", 0); // the default again, same bus
            assertThat(busServiceId()).isEqualTo(busId);
        } finally {
            blocked.open(); // never leave a delivery worker blocked for the next test
        }
    }

    /** bus:publish, called as Gogo calls it, reaches a typed behaviour in another bundle with its own class. */
    @Test
    void busPublishDeliversAnUntypedEventToATypedBehaviourOfAnotherBundle(
            @InjectInstalledBundle(value = "tb.publish.target.jar", start = true) Bundle target)
            throws Exception {
        BusTestSupport behaviours = new BusTestSupport(context);
        Recorder acks = new Recorder();
        behaviours.untyped(acks, CopyConsumerActivator.ACK);
        await().atMost(DEADLINE).until(() -> stats.consumers().stream()
                .anyMatch(c -> c.bundle.equals("tb.publish.target")));
        ServiceReference<?>[] refs = context.getServiceReferences((String) null,
                "(&(osgi.command.scope=bus)(osgi.command.function=publish))");
        assertThat(refs).hasSize(1);
        Object commands = context.getService(refs[0]);
        Method publish = commands.getClass().getMethod("publish", String.class, String[].class);
        Object answer = publish.invoke(commands, CopyEvent.class.getName(),
                new String[] { "robotId=\"robot 9\"", "at.x=5", "at.y=-2" });
        assertThat(String.valueOf(answer)).startsWith("Published " + CopyEvent.class.getName());

        await().atMost(DEADLINE).until(() -> acks.maps.size() == 1);
        assertThat(acks.maps.get(0)).containsEntry("ownClass", true).containsEntry("robotId", "robot 9")
                .containsEntry("x", 5);

        Object error = publish.invoke(commands, CopyEvent.class.getName(), new String[] { "robotId" });
        assertThat(String.valueOf(error)).contains("field 1 \"robotId\" is not key=value").contains("usage");
    }

    private ConsumerStatistics queueOf(GatedBehaviour behaviour) {
        return stats.consumers().stream().filter(c -> "(robotId=reconfigured)".equals(c.filter)).findFirst()
                .orElse(null);
    }

    private EventTypeStatistics statsOf(String type) {
        return stats.eventTypes().stream().filter(s -> s.eventType.equals(type)).findFirst()
                .orElseGet(EventTypeStatistics::new);
    }

    private long busServiceId() {
        ServiceReference<EventBus> ref = context.getServiceReference(EventBus.class);
        return ref == null ? -1 : (Long) ref.getProperty(Constants.SERVICE_ID);
    }
}
