package eu.brain.iot.benchmarks.driver.typedevent;

import java.util.Dictionary;
import java.util.Hashtable;

import org.osgi.framework.BundleContext;
import org.osgi.service.typedevent.TypedEventBus;
import org.osgi.service.typedevent.TypedEventConstants;
import org.osgi.service.typedevent.TypedEventHandler;

import eu.brain.iot.benchmarks.driver.common.DriverActivator;
import eu.brain.iot.benchmarks.driver.common.PublishingDriver;
import eu.brain.iot.benchmarks.driver.common.Registrations;
import eu.brain.iot.benchmarks.spi.BusDriver;
import eu.brain.iot.benchmarks.spi.ConsumerProbe;

/**
 * Drives the OSGi Typed Event bus: {@link TypedEventBus#deliver(Object)} of a {@link Position} (topic from its
 * class name); consumers are {@link TypedEventHandler} services naming the event type.
 */
public final class TypedEventDriverActivator extends DriverActivator<TypedEventBus> {

    public TypedEventDriverActivator() {
        super(TypedEventBus.class);
    }

    @Override
    protected BusDriver driver(BundleContext context, TypedEventBus bus) {
        return new PublishingDriver() {
            @Override
            protected void publish(String robotId, int x, int y, long sentNanos) {
                Position event = new Position();
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
                    props.put(TypedEventConstants.TYPED_EVENT_TYPE, Position.class.getName());
                    registrations.add(context.registerService(TypedEventHandler.class, new ProbeHandler(probe), props));
                }
                return registrations;
            }
        };
    }
}
