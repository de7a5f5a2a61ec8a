package eu.brain.iot.eventing.integration.tb;

import java.util.HashMap;
import java.util.Hashtable;
import java.util.Map;

import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * Runs inside a behaviour bundle installed while events it consumes are held: consumes {@link HoldEvent} (its
 * own copy of the class) and answers each with an untyped {@code HeldAck} event carrying publisher and sequence.
 */
public class HoldConsumerActivator implements BundleActivator {

    public static final String ACK = "eu.brain.iot.eventing.integration.tb.HeldAck";

    @Override
    public void start(BundleContext context) {
        EventBus bus = context.getService(context.getServiceReference(EventBus.class));
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("eu.brain.iot.behaviour.consumed", new String[] { HoldEvent.class.getName() });
        props.put("eu.brain.iot.behaviour.name", "held-events-consumer");
        SmartBehaviour<HoldEvent> consumer = event -> {
            Map<String, Object> ack = new HashMap<>();
            ack.put("publisher", event.publisher);
            ack.put("seq", event.seq);
            ack.put("ownClass", event.getClass() == HoldEvent.class);
            bus.deliver(ACK, ack);
        };
        context.registerService(SmartBehaviour.class, consumer, props);
    }

    @Override
    public void stop(BundleContext context) {
        // services are unregistered by the framework
    }
}
