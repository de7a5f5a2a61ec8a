package eu.brain.iot.eventing.integration.tb;

import java.util.HashMap;
import java.util.Hashtable;
import java.util.concurrent.CountDownLatch;

import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * Runs inside a bundle whose behaviour gets stuck on its first event (it announces that with an untyped
 * {@code Stuck} event) until its thread is interrupted, so that events pile up in its queue.
 */
public class BlockingConsumerActivator implements BundleActivator {

    public static final String STUCK = "eu.brain.iot.eventing.integration.tb.Stuck";

    @Override
    public void start(BundleContext context) {
        EventBus bus = context.getService(context.getServiceReference(EventBus.class));
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("eu.brain.iot.behaviour.consumed", new String[] { CopyEvent.class.getName() });
        props.put("eu.brain.iot.behaviour.name", "stuck-behaviour");
        SmartBehaviour<CopyEvent> consumer = event -> {
            bus.deliver(STUCK, new HashMap<>());
            try {
                new CountDownLatch(1).await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        };
        context.registerService(SmartBehaviour.class, consumer, props);
    }

    @Override
    public void stop(BundleContext context) {
        // services are unregistered by the framework
    }
}
