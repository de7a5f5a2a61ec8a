package eu.brain.iot.bms.impl;

import java.util.function.BooleanSupplier;
import java.util.function.ObjLongConsumer;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.BundleListener;

/**
 * Tells the BMS when a bundle stops or is uninstalled, so that a behaviour whose bundle went away outside the
 * installer comes back without waiting for an event ({@link Revivals}). An asynchronous {@link BundleListener}: the
 * framework's event thread only checks that the framework is not shutting down and queues the bundle's symbolic name
 * and id on the BMS's thread ({@link Scheduler}); it never calls the installer nor waits. Whether the bundle is a
 * behaviour the installer installed is decided there, after {@code restart.grace.ms}.
 * <p>
 * Threads: {@link #open} and {@link #close} on the component's (activation, deactivation); {@link #bundleChanged} on
 * the framework's event thread. No state besides final fields.
 */
final class BundleWatch implements BundleListener {

    private final BundleContext context;
    private final Scheduler scheduler;
    private final BooleanSupplier frameworkStopping;
    private final ObjLongConsumer<String> wentAway;

    /**
     * @param frameworkStopping {@link #frameworkStopping(BundleContext)}
     * @param wentAway run on the BMS's thread with the symbolic name and id of a bundle that stopped or went
     */
    BundleWatch(BundleContext context, Scheduler scheduler, BooleanSupplier frameworkStopping,
            ObjLongConsumer<String> wentAway) {
        this.context = context;
        this.scheduler = scheduler;
        this.frameworkStopping = frameworkStopping;
        this.wentAway = wentAway;
    }

    /**
     * @return whether the framework is shutting down (its system bundle stopping): nothing is brought back then. Asks
     *         the system bundle itself, which answers from any thread, also once the BMS's bundle context is gone.
     */
    static BooleanSupplier frameworkStopping(BundleContext context) {
        Bundle system = context.getBundle(0);
        return () -> system.getState() == Bundle.STOPPING;
    }

    void open() {
        context.addBundleListener(this);
    }

    void close() {
        try {
            context.removeBundleListener(this);
        } catch (IllegalStateException e) {
            // our bundle is stopping: the framework removes the listener itself
        }
    }

    @Override
    public void bundleChanged(BundleEvent event) {
        // an uninstall of an active bundle stops it first: both events come, the first one counts
        if ((event.getType() != BundleEvent.STOPPED && event.getType() != BundleEvent.UNINSTALLED)
                || frameworkStopping.getAsBoolean()) {
            return;
        }
        Bundle bundle = event.getBundle();
        String symbolicName = bundle.getSymbolicName();
        long id = bundle.getBundleId();
        if (symbolicName != null && id != 0) {
            scheduler.execute(() -> wentAway.accept(symbolicName, id));
        }
    }
}
