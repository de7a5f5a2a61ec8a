package eu.brain.iot.benchmarks.driver.eventadmin;

import java.util.Dictionary;
import java.util.HashMap;
import java.util.Hashtable;
import java.util.Map;

import org.osgi.framework.BundleContext;
import org.osgi.service.event.Event;
import org.osgi.service.event.EventAdmin;
import org.osgi.service.event.EventConstants;
import org.osgi.service.event.EventHandler;

import eu.brain.iot.benchmarks.driver.common.DriverActivator;
import eu.brain.iot.benchmarks.driver.common.PublishingDriver;
import eu.brain.iot.benchmarks.driver.common.Registrations;
import eu.brain.iot.benchmarks.spi.BusDriver;
import eu.brain.iot.benchmarks.spi.ConsumerProbe;

/**
 * Drives OSGi Event Admin: {@link EventAdmin#postEvent(Event)} (asynchronous delivery) of an event whose four
 * properties are the benchmark fields; consumers are {@link EventHandler} services on the topic.
 */
public final class EventAdminDriverActivator extends DriverActivator<EventAdmin> {

    static final String TOPIC = "eu/brain/iot/benchmarks/Position";

    public EventAdminDriverActivator() {
        super(EventAdmin.class);
    }

    @Override
    protected BusDriver driver(BundleContext context, EventAdmin eventAdmin) {
        return new PublishingDriver() {
            @Override
            protected void publish(String robotId, int x, int y, long sentNanos) {
                Map<String, Object> properties = new HashMap<>(8);
                properties.put("robotId", robotId);
                properties.put("x", x);
                properties.put("y", y);
                properties.put("sentNanos", sentNanos);
                eventAdmin.postEvent(new Event(TOPIC, properties));
            }

            @Override
            public AutoCloseable registerConsumers(ConsumerProbe[] probes) {
                Registrations registrations = new Registrations();
                for (ConsumerProbe probe : probes) {
                    Dictionary<String, Object> props = new Hashtable<>();
                    props.put(EventConstants.EVENT_TOPIC, TOPIC);
                    EventHandler handler = event -> probe.onEvent((Long) event.getProperty("sentNanos"));
                    registrations.add(context.registerService(EventHandler.class, handler, props));
                }
                return registrations;
            }
        };
    }
}
