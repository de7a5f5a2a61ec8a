package eu.brain.iot.eventing.integration.listing3;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.wiring.BundleCapability;
import org.osgi.framework.wiring.BundleRevision;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/** A behaviour written as in the paper's Listing 3 is found by the bus and advertised to repositories. */
class Listing3IntegrationTest {

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 5000)
    EventBus bus;

    @Test
    void theListing3BehaviourReceivesItsEventsThroughTheBus() throws Exception {
        @SuppressWarnings("rawtypes")
        ServiceReference<SmartBehaviour> robotA = context
                .getServiceReferences(SmartBehaviour.class, "(eu.brain.iot.behaviour.name=Smart RobotA)").iterator().next();
        assertThat(robotA.getProperty("eu.brain.iot.behaviour.consumed"))
                .isEqualTo(new String[] { IresolveCollision.class.getName() });
        assertThat(robotA.getProperty("eu.brain.iot.behaviour.author")).isEqualTo("UGA");

        IresolveCollision event = new IresolveCollision();
        event.robotId = "robot2";
        bus.deliver(event);

        await().atMost(Duration.ofSeconds(10)).until(() -> RobotImpl.resolveCollision != null);
        assertThat(RobotImpl.resolveCollision.robotId).isEqualTo("robot2");
        assertThat(RobotImpl.resolveCollision.resolved).isTrue();
        assertThat(event.resolved).as("the publisher's object is not the one the behaviour changed").isFalse();
    }

    @Test
    void theBundleAdvertisesTheConsumedEventsAsACapability() {
        List<BundleCapability> caps = context.getBundle().adapt(BundleRevision.class)
                .getDeclaredCapabilities("eu.brain.iot.behaviour");
        assertThat(caps).anySatisfy(cap -> {
            Map<String, Object> attrs = cap.getAttributes();
            assertThat(attrs.get("consumed")).isEqualTo(List.of(IresolveCollision.class.getName()));
            assertThat(attrs.get("name")).isEqualTo("Smart RobotA");
        });
    }
}
