package eu.brain.iot.eventing.integration.tb;

import java.util.HashMap;
import java.util.Hashtable;
import java.util.Map;

import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * Runs inside a bundle that has its own copy of {@link CopyEvent}: consumes it and answers with an untyped
 * {@code Ack} event telling whether the event it got is an instance of its own class.
 */
public class CopyConsumerActivator implements BundleActivator {

    public static final String ACK = "eu.brain.iot.eventing.integration.tb.Ack";

    @Override
    public void start(BundleContext context) {
        EventBus bus = context.getService(context.getServiceReference(EventBus.class));
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("eu.brain.iot.behaviour.consumed", new String[] { CopyEvent.class.getName() });
        SmartBehaviour<CopyEvent> consumer = event -> {
            Map<String, Object> ack = new HashMap<>();
            ack.put("ownClass", event.getClass() == CopyEvent.class);
            ack.put("robotId", event.robotId);
            ack.put("x", event.at == null ? -1 : event.at.x);
            ack.put("bundle", context.getBundle().getSymbolicName());
            bus.deliver(ACK, ack);
        };
        context.registerService(SmartBehaviour.class, consumer, props);
    }

    @Override
    public void stop(BundleContext context) {
        // services are unregistered by the framework
    }
}
