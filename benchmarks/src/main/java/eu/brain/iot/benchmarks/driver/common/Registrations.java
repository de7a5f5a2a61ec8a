package eu.brain.iot.benchmarks.driver.common;

import java.util.ArrayList;
import java.util.List;

import org.osgi.framework.ServiceRegistration;

/** Consumer services registered for one benchmark phase; closing unregisters them all. */
public final class Registrations implements AutoCloseable {

    private final List<ServiceRegistration<?>> registrations = new ArrayList<>();

    public void add(ServiceRegistration<?> registration) {
        registrations.add(registration);
    }

    @Override
    public void close() {
        registrations.forEach(ServiceRegistration::unregister);
        registrations.clear();
    }
}
