package eu.brain.iot.eventing.integration;

import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.Hashtable;

import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;

import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;

/**
 * Registers behaviours as services, as a bundle with @SmartBehaviourDefinition would. Give it the test's
 * {@code @InjectBundleContext} context: that is osgi-test's {@code CloseableBundleContext}, which unregisters every
 * service registered through it when the test ends, so nothing here needs a clean-up of its own.
 */
final class BusTestSupport {
    private final BundleContext context;

    /**
     * Wait until the bus has applied a configuration change in place: Declarative Services calls the bus's
     * modified method first, then updates its service properties, so seeing the property means it is applied.
     *
     * @param value the expected value of the property; the bus's service always carries every setting (bnd declares
     *        the defaults of its configuration type as component properties), so after a deletion: the default
     */
    static void awaitBusProperty(BundleContext context, String key, Object value) {
        await().atMost(Duration.ofSeconds(10)).until(() -> {
            ServiceReference<EventBus> ref = context.getServiceReference(EventBus.class);
            return ref != null && String.valueOf(value).equals(String.valueOf(ref.getProperty(key)));
        });
    }

    BusTestSupport(BundleContext context) {
        this.context = context;
    }

    ServiceRegistration<?> typed(SmartBehaviour<?> behaviour, String filter, Class<?>... consumed) {
        Hashtable<String, Object> props = props(filter, consumed);
        return context.registerService(SmartBehaviour.class.getName(), behaviour, props);
    }

    ServiceRegistration<?> untyped(UntypedSmartBehaviour behaviour, String... consumed) {
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, consumed);
        return context.registerService(UntypedSmartBehaviour.class, behaviour, props);
    }

    ServiceRegistration<?> lastResort(UntypedSmartBehaviour behaviour) {
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(SmartBehaviourNamespace.LAST_RESORT_PROPERTY, Boolean.TRUE);
        return context.registerService(UntypedSmartBehaviour.class, behaviour, props);
    }

    private static Hashtable<String, Object> props(String filter, Class<?>... consumed) {
        Hashtable<String, Object> props = new Hashtable<>();
        String[] names = new String[consumed.length];
        for (int i = 0; i < consumed.length; i++) {
            names[i] = consumed[i].getName();
        }
        props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, names);
        if (filter != null) {
            props.put(SmartBehaviourNamespace.FILTER_PROPERTY, filter);
        }
        return props;
    }
}
