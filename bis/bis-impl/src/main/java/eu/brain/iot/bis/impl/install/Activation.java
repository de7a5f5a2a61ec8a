package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceListener;
import org.osgi.framework.ServiceReference;

import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * Waits until a behaviour bundle's smart behaviours are registered with the bus: the bundle has registered at least
 * one service with the {@code eu.brain.iot.behaviour.consumed} property, and the bus's statistics list every such
 * service (when the bus offers its statistics; without them, registration alone counts). A service listener wakes
 * the waiting thread at each registration; between them it looks again every {@value #RECHECK_MILLIS} ms, because the
 * bus takes the service in its own listener, whose turn may come after ours.
 * <p>
 * Threads: {@link #await} blocks the installer's thread; the framework's threads only signal.
 */
final class Activation {

    static final long RECHECK_MILLIS = 2;
    private static final String FILTER = "(" + SmartBehaviourNamespace.CONSUMED_PROPERTY + "=*)";

    private final BundleContext context;
    private final Supplier<EventBusStatistics> statistics;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();

    Activation(BundleContext context, Supplier<EventBusStatistics> statistics) {
        this.context = context;
        this.statistics = statistics;
    }

    /** @return the service ids of the bundle's smart behaviours, or null when the time ran out */
    List<Long> await(Bundle bundle, long timeoutMillis) throws InterruptedException {
        ServiceListener listener = event -> signal();
        try {
            context.addServiceListener(listener, FILTER);
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(FILTER, e);
        }
        try {
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
            while (true) {
                List<Long> ids = registered(bundle);
                if (!ids.isEmpty() && knownToBus(ids)) {
                    return ids;
                }
                long left = deadline - System.nanoTime();
                if (left <= 0 || bundle.getState() == Bundle.UNINSTALLED) {
                    return null;
                }
                lock.lock();
                try {
                    changed.await(Math.min(left, TimeUnit.MILLISECONDS.toNanos(RECHECK_MILLIS)),
                            TimeUnit.NANOSECONDS);
                } finally {
                    lock.unlock();
                }
            }
        } finally {
            context.removeServiceListener(listener);
        }
    }

    /**
     * @return for a message, what stands between the bundle and the bus now: no smart behaviour registered, or those
     *         registered that the bus does not list (its statistics)
     */
    String missing(Bundle bundle) {
        List<Long> ids = registered(bundle);
        if (ids.isEmpty()) {
            return "the bundle registered no smart behaviour";
        }
        List<Long> known = listedByBus();
        if (known == null) {
            return "the bundle registered smart behaviours " + ids;
        }
        List<Long> unknown = ids.stream().filter(id -> !known.contains(id)).toList();
        return "the bundle registered smart behaviours " + ids + (unknown.isEmpty() ? ", all listed by the bus"
                : ", of which the bus does not list " + unknown);
    }

    /** @return whether the bundle has registered smart behaviours now */
    static boolean hasBehaviours(Bundle bundle) {
        return !registered(bundle).isEmpty();
    }

    private boolean knownToBus(List<Long> ids) {
        List<Long> known = listedByBus();
        return known == null || known.containsAll(ids);
    }

    /** @return the service ids of the consumers the bus lists, or null when it offers no statistics */
    private List<Long> listedByBus() {
        EventBusStatistics bus = statistics.get();
        if (bus == null) {
            return null;
        }
        List<Long> known = new ArrayList<>();
        bus.consumers().forEach(c -> known.add(c.serviceId));
        return known;
    }

    private static List<Long> registered(Bundle bundle) {
        List<Long> ids = new ArrayList<>();
        ServiceReference<?>[] refs = bundle.getState() == Bundle.ACTIVE ? bundle.getRegisteredServices() : null;
        if (refs != null) {
            for (ServiceReference<?> ref : refs) {
                if (ref.getProperty(SmartBehaviourNamespace.CONSUMED_PROPERTY) != null) {
                    ids.add((Long) ref.getProperty(Constants.SERVICE_ID));
                }
            }
        }
        return ids;
    }

    private void signal() {
        lock.lock();
        try {
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }
}
