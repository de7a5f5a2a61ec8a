package eu.brain.iot.edge.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.Hashtable;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.service.component.runtime.ServiceComponentRuntime;
import org.osgi.service.component.runtime.dto.ComponentConfigurationDTO;
import org.osgi.service.component.runtime.dto.ComponentDescriptionDTO;
import org.osgi.service.log.LogListener;
import org.osgi.service.log.LogReaderService;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.edge.model.api.DeviceModel;

/**
 * The edge starts once and stays started: it is active before anyone uses it, a user coming and going does not
 * rebuild it, and a configuration arriving later is applied in place. (As a delayed component it was built for its
 * first user and thrown away when that user let go: "edge polling the fleet" twice at every node boot.)
 */
class EdgeStartsOnceIntegrationTest {

    private static final String ACTIVATED = "edge polling the fleet";

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 10_000)
    ServiceComponentRuntime scr;

    @InjectService(timeout = 10_000)
    LogReaderService logs;

    @InjectService(timeout = 10_000)
    ConfigurationAdmin cm;

    @Test
    void theEdgeStartsOnceWhateverItsUsersAndConfigurationDo() throws Exception {
        ComponentDescriptionDTO edge = scr.getComponentDescriptionDTOs().stream()
                .filter(d -> d.name.equals("eu.brain.iot.edge.impl.EdgeComponent")).findFirst().orElseThrow();
        // here the REST API holds the edge from the start, so a delayed edge would pass what follows: the node's
        // boot let go of it (NodeLogTest counts its starts there); an immediate component is never disposed for that
        assertThat(edge.immediate).as("the edge is started at once, not for its first user").isTrue();
        await("the edge active with no user asking for it").atMost(EdgeTestSupport.DEADLINE)
                .until(() -> scr.getComponentConfigurationDTOs(edge).stream()
                        .anyMatch(c -> c.state == ComponentConfigurationDTO.ACTIVE));

        AtomicInteger activations = new AtomicInteger();
        LogListener counter = e -> {
            if (e.getLoggerName().equals("eu.brain.iot.edge.impl.EdgeComponent") && e.getMessage().startsWith(ACTIVATED)) {
                activations.incrementAndGet();
            }
        };
        logs.addLogListener(counter);
        Configuration config = cm.getConfiguration(EdgeTestSupport.EDGE_PID, "?");
        try {
            for (int i = 0; i < 3; i++) { // a user comes and goes
                ServiceReference<DeviceModel> ref = context.getServiceReference(DeviceModel.class);
                assertThat(context.getService(ref).providers()).isNotNull();
                context.ungetService(ref);
            }
            config.update(new Hashtable<>(Map.of("poll.period.ms", 700L))); // a configuration arrives (File Install, the shell)
            await("the new configuration applied").atMost(EdgeTestSupport.DEADLINE).until(() -> scr
                    .getComponentConfigurationDTOs(edge).stream()
                    .anyMatch(c -> c.state == ComponentConfigurationDTO.ACTIVE
                            && Long.valueOf(700L).equals(c.properties.get("poll.period.ms"))));
            ServiceReference<DeviceModel> ref = context.getServiceReference(DeviceModel.class);
            context.getService(ref);
            context.ungetService(ref);
            // log listeners are called asynchronously: a late start would show within this time
            await("no second start").during(Duration.ofMillis(500)).atMost(Duration.ofSeconds(2))
                    .until(() -> activations.get() == 0);
        } finally {
            logs.removeLogListener(counter);
            config.delete();
        }
    }
}
