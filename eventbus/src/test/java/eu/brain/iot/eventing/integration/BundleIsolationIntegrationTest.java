package eu.brain.iot.eventing.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectInstalledBundle;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.integration.tb.BlockingConsumerActivator;
import eu.brain.iot.eventing.integration.tb.CopyEvent;
import eu.brain.iot.eventing.integration.tb.CopyConsumerActivator;
import eu.brain.iot.eventing.integration.tb.Position;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/**
 * Behaviours in bundles of their own: private copies of event classes, and bundles that stop mid-stream. The
 * bundles are the jars made from src/test/bundles/*.bnd and embedded in the test bundle; osgi-test installs them
 * through the test's bundle context, which uninstalls them when the test ends.
 */
class BundleIsolationIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 5000)
    EventBus bus;

    @InjectService(timeout = 5000)
    EventBusStatistics stats;

    BusTestSupport behaviours;
    int baseline;

    @BeforeEach
    void setUp() {
        behaviours = new BusTestSupport(context);
        baseline = stats.consumers().size(); // behaviours other tests' bundles keep registered
    }

    private static CopyEvent copyEvent(String robot, int x) {
        CopyEvent event = new CopyEvent();
        event.robotId = robot;
        event.at = new Position();
        event.at.x = x;
        return event;
    }

    private EventTypeStatistics statsOf(String type) {
        return stats.eventTypes().stream().filter(s -> s.eventType.equals(type)).findFirst()
                .orElseGet(EventTypeStatistics::new);
    }

    @Test
    void bundlesWithTheirOwnCopyOfAnEventClassReceiveInstancesOfTheirOwnClass(
            @InjectInstalledBundle(value = "tb.copy.one.jar", start = true) Bundle one,
            @InjectInstalledBundle(value = "tb.copy.two.jar", start = true) Bundle two) throws Exception {
        Recorder acks = new Recorder();
        behaviours.untyped(acks, CopyConsumerActivator.ACK);
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers()).hasSize(baseline + 3));
        assertThat(one.loadClass(CopyEvent.class.getName())).isNotSameAs(CopyEvent.class);
        assertThat(two.loadClass(CopyEvent.class.getName())).isNotSameAs(one.loadClass(CopyEvent.class.getName()));

        bus.deliver(copyEvent("robot1", 7));

        await().atMost(DEADLINE).until(() -> acks.maps.size() == 2);
        assertThat(acks.maps).allSatisfy(ack -> {
            assertThat(ack).containsEntry("ownClass", true).containsEntry("robotId", "robot1").containsEntry("x", 7);
        });
        assertThat(acks.maps).extracting(ack -> ack.get("bundle")).containsExactlyInAnyOrder("tb.copy.one", "tb.copy.two");
    }

    @Test
    void aBundleStoppedWithQueuedEventsLeavesNoThreadAndNoExceptionStorm(
            @InjectInstalledBundle(value = "tb.stuck.jar", start = true) Bundle bundle) throws Exception {
        Recorder stuck = new Recorder();
        behaviours.untyped(stuck, BlockingConsumerActivator.STUCK);
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers()).hasSize(baseline + 2));

        bus.deliver(copyEvent("robot1", 0));
        await().atMost(DEADLINE).until(() -> stuck.maps.size() == 1);
        for (int i = 1; i <= 500; i++) {
            bus.deliver(copyEvent("robot1", i));
        }
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers())
                .anySatisfy(c -> assertThat(c.queueDepth).isEqualTo(500)));
        EventTypeStatistics before = statsOf(CopyEvent.class.getName());

        bundle.stop();

        await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers()).hasSize(baseline + 1));
        await().atMost(DEADLINE).untilAsserted(() -> {
            EventTypeStatistics after = statsOf(CopyEvent.class.getName());
            assertThat(after.discarded - before.discarded).isEqualTo(500);
            assertThat(after.failed).isEqualTo(before.failed);
        });
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(Thread.getAllStackTraces().keySet())
                .noneMatch(t -> t.getName().startsWith("brain-iot-bus[stuck-behaviour")));
    }
}
