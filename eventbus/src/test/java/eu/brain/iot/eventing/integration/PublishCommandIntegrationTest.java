package eu.brain.iot.eventing.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.eventing.integration.exported.Command;
import eu.brain.iot.eventing.integration.exported.StopCommand;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * {@code bus:publish} of a type no bundle knows says so and suggests the known names nearest to it; one of a class a
 * bundle exports is published as that class, so that the consumers of its supertypes take it.
 */
class PublishCommandIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    @InjectBundleContext
    BundleContext context;

    @InjectService
    EventBusStatistics stats;

    @Test
    void anEventOfAnExportedClassReachesTheConsumersOfItsSupertype() throws Exception {
        Recorder recorder = new Recorder();
        ServiceRegistration<?> reg = new BusTestSupport(context).typed(recorder, null, Command.class);
        try {
            await().atMost(DEADLINE).until(() -> stats.consumers().stream()
                    .anyMatch(c -> c.consumed.contains(Command.class.getName())));
            assertThat(new BusShell(context).publish(StopCommand.class.getName(), "deviceId=robot7"))
                    .startsWith("Published ");
            await().atMost(DEADLINE).until(() -> recorder.events.size() == 1);
            assertThat(recorder.events.get(0)).isInstanceOfSatisfying(StopCommand.class,
                    stop -> assertThat(stop.deviceId).isEqualTo("robot7"));
        } finally {
            reg.unregister();
        }
    }

    @Test
    void aTypoOrAWrongCaseIsRefusedWithTheNearestKnownNames() throws Exception {
        Recorder recorder = new Recorder();
        new BusTestSupport(context).typed(recorder, null, PositionEvent.class);
        await().atMost(DEADLINE).until(() -> stats.consumers().stream()
                .anyMatch(c -> c.consumed.contains(PositionEvent.class.getName())));
        BusShell shell = new BusShell(context);

        String wrongCase = PositionEvent.class.getName().toLowerCase();
        assertThat(shell.publish(wrongCase, "robotId=robot1"))
                .contains("no class named " + wrongCase + " is known")
                .contains("did you mean " + PositionEvent.class.getName())
                .contains("Nothing was published");
        // a class of a package a bundle exports, one letter off
        assertThat(shell.publish("eu.brain.iot.eventing.api.BrainIoTEvnt"))
                .contains("did you mean eu.brain.iot.eventing.api.BrainIoTEvent");
        // the package left out
        assertThat(shell.publish("PositionEvent")).contains("did you mean " + PositionEvent.class.getName());
        assertThat(stats.eventTypes()).extracting(t -> t.eventType).doesNotContain(wrongCase, "PositionEvent",
                "eu.brain.iot.eventing.api.BrainIoTEvnt");

        assertThat(shell.publish(PositionEvent.class.getName(), "robotId=robot1")).startsWith("Published ")
                .doesNotContain("known");
        await().atMost(DEADLINE).until(() -> recorder.events.size() == 1);

        String faraway = "org.example.Greeting";
        assertThat(shell.publish(faraway, "text=hello")).startsWith("Published " + faraway)
                .contains("No class of that name is known on this node");
    }
}
