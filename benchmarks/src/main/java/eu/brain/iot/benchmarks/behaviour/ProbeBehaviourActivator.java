package eu.brain.iot.benchmarks.behaviour;

import java.util.Hashtable;

import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;

import eu.brain.iot.benchmarks.behaviour.event.InstallBenchEvent;
import eu.brain.iot.benchmarks.spi.InstallProbe;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The probe behaviour, in a bundle of its own that only the repository holds: registers a smart behaviour for
 * {@link InstallBenchEvent} that reports every event to the launcher's {@link InstallProbe} from inside
 * {@code notify()}. A plain activator rather than a DS component, so that its start costs what a small behaviour's
 * does without depending on SCR's timing.
 */
public final class ProbeBehaviourActivator implements BundleActivator {

    @Override
    public void start(BundleContext context) {
        ServiceReference<InstallProbe> ref = context.getServiceReference(InstallProbe.class);
        InstallProbe probe = context.getService(ref);
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { InstallBenchEvent.class.getName() });
        props.put(SmartBehaviourNamespace.PROPERTY_PREFIX + SmartBehaviourNamespace.NAME, "install-probe");
        SmartBehaviour<InstallBenchEvent> behaviour = e -> probe.onEvent(e.publisher, e.seq, e.sentNanos);
        context.registerService(SmartBehaviour.class, behaviour, props);
    }

    @Override
    public void stop(BundleContext context) {
        // the framework unregisters the service
    }
}
