package eu.brain.iot.bms.integration.tb;

import java.util.HashMap;
import java.util.Hashtable;
import java.util.Map;

import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The behaviour of the test repository's bundle {@code tb.bms.orders} (its own copies of {@link Order} and
 * {@link Refill}): answers every event it receives with an untyped {@value #ACK} event saying which type,
 * publisher and sequence number it got, so that the test sees what reached {@code notify()} and in which order.
 */
public class OrderBehaviourActivator implements BundleActivator {

    public static final String ACK = "eu.brain.iot.bms.integration.tb.Ack";
    /** While this system property is {@code true}, the bundle fails to start, as a broken behaviour would. */
    public static final String FAIL_START = "tb.bms.orders.failStart";

    @Override
    public void start(BundleContext context) {
        if (Boolean.getBoolean(FAIL_START)) {
            throw new IllegalStateException("the test asks tb.bms.orders to fail to start (" + FAIL_START + ")");
        }
        EventBus bus = context.getService(context.getServiceReference(EventBus.class));
        Hashtable<String, Object> props = new Hashtable<>();
        props.put("eu.brain.iot.behaviour.consumed", new String[] { Order.class.getName(), Refill.class.getName() });
        props.put("eu.brain.iot.behaviour.name", "orders");
        SmartBehaviour<BrainIoTEvent> behaviour = event -> {
            Map<String, Object> ack = new HashMap<>();
            ack.put("type", event.getClass().getName());
            ack.put("ownClass", event.getClass().getClassLoader() == OrderBehaviourActivator.class.getClassLoader());
            ack.put("nanoTime", System.nanoTime());
            if (event instanceof Order o) {
                ack.put("publisher", o.publisher);
                ack.put("seq", o.seq);
            } else if (event instanceof Refill r) {
                ack.put("publisher", r.publisher);
                ack.put("seq", r.seq);
            }
            bus.deliver(ACK, ack);
        };
        context.registerService(SmartBehaviour.class, behaviour, props);
    }

    @Override
    public void stop(BundleContext context) {
        // the framework unregisters the service
    }
}
