package eu.brain.iot.benchmarks.driver.ours;

import java.util.Dictionary;
import java.util.Hashtable;

import org.osgi.framework.BundleContext;

import eu.brain.iot.benchmarks.driver.common.DriverActivator;
import eu.brain.iot.benchmarks.driver.common.PublishingDriver;
import eu.brain.iot.benchmarks.driver.common.Registrations;
import eu.brain.iot.benchmarks.spi.BusDriver;
import eu.brain.iot.benchmarks.spi.ConsumerProbe;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * Drives our bus: {@link EventBus#deliver(eu.brain.iot.eventing.api.BrainIoTEvent)} of a {@link PositionEvent},
 * consumers registered as {@link SmartBehaviour} services with the service property the bus reads (what
 * {@code @SmartBehaviourDefinition(consumed = PositionEvent.class)} generates on a DS component).
 */
public final class OurBusDriverActivator extends DriverActivator<EventBus> {

    public OurBusDriverActivator() {
        super(EventBus.class);
    }

    @Override
    protected BusDriver driver(BundleContext context, EventBus bus) {
        return new PublishingDriver() {
            @Override
            protected void publish(String robotId, int x, int y, long sentNanos) {
                PositionEvent event = new PositionEvent();
                event.robotId = robotId;
                event.x = x;
                event.y = y;
                event.sentNanos = sentNanos;
                bus.deliver(event);
            }

            @Override
            public AutoCloseable registerConsumers(ConsumerProbe[] probes) {
                Registrations registrations = new Registrations();
                for (ConsumerProbe probe : probes) {
                    Dictionary<String, Object> props = new Hashtable<>();
                    props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { PositionEvent.class.getName() });
                    registrations.add(context.registerService(SmartBehaviour.class, new ProbeBehaviour(probe), props));
                }
                return registrations;
            }
        };
    }
}
