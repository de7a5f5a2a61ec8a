package eu.brain.iot.benchmarks.driver.common;

import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.osgi.util.tracker.ServiceTracker;

import eu.brain.iot.benchmarks.spi.BusDriver;

/**
 * Registers a {@link BusDriver} once the bus service {@code S} is there, and withdraws it when the bus goes.
 * Ownership: the tracker's callbacks, which the framework serialises per tracked service.
 *
 * @param <S> the bus's service type
 */
public abstract class DriverActivator<S> implements BundleActivator {

    private final Class<S> busType;
    private ServiceTracker<S, ServiceRegistration<BusDriver>> tracker;

    protected DriverActivator(Class<S> busType) {
        this.busType = busType;
    }

    /** Make the driver for this bus, with this bundle's context for registering consumers. */
    protected abstract BusDriver driver(BundleContext context, S bus);

    @Override
    public void start(BundleContext context) {
        tracker = new ServiceTracker<>(context, busType, null) {
            @Override
            public ServiceRegistration<BusDriver> addingService(ServiceReference<S> reference) {
                S bus = context.getService(reference);
                return bus == null ? null : context.registerService(BusDriver.class, driver(context, bus), null);
            }

            @Override
            public void removedService(ServiceReference<S> reference, ServiceRegistration<BusDriver> registration) {
                registration.unregister();
                context.ungetService(reference);
            }
        };
        tracker.open();
    }

    @Override
    public void stop(BundleContext context) {
        tracker.close();
    }
}
