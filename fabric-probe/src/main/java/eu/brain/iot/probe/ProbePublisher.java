package eu.brain.iot.probe;

import eu.brain.iot.eventing.api.EventBus;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Filter;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.util.tracker.ServiceTracker;

/**
 * Publishes one run of probe events on this node's bus, once a consumer of them is known here (the federation's
 * forwarder for another node's behaviour, or a behaviour of this node), paced at the configured rate or back to
 * back. Prints {@code probe publisher: run=R consumer known} then
 * {@code probe publisher: run=R published=N startNs=T} (T: {@code System.nanoTime()} before the first event).
 * With {@code consumer.timeout.s=0} it publishes at once, whether a consumer is known or not, and prints only the
 * second line: an event nobody takes yet is then the node's Behaviour Management Service's to hold and to have a
 * behaviour installed for, on this node or another (the benchmark's remote install on demand).
 *
 * <p>Threads: one publishing thread per activation, started and stopped (interrupted, joined) by SCR's thread.
 */
@Component(configurationPid = ProbePublisherConfig.PID, configurationPolicy = ConfigurationPolicy.REQUIRE,
        service = {})
public final class ProbePublisher {
    /** {@code consumer.timeout.s} that publishes at once, without waiting for a consumer. */
    static final int PUBLISH_AT_ONCE = 0;
    private static final String CONSUMED = "eu.brain.iot.behaviour.consumed";

    private final Thread thread;

    @Activate
    public ProbePublisher(@Reference EventBus bus, ProbePublisherConfig config, BundleContext context) {
        thread = new Thread(() -> publish(bus, config, context), "probe-publisher-" + config.run());
        thread.start();
    }

    private static void publish(EventBus bus, ProbePublisherConfig config, BundleContext context) {
        String run = config.run();
        try {
            if (config.consumer_timeout_s() != PUBLISH_AT_ONCE && !awaitConsumer(config, context)) {
                System.out.println("probe publisher: run=" + run + " no consumer of probe events within "
                        + config.consumer_timeout_s() + " s; nothing published");
                return;
            }
            boolean paced = config.rate() > 0;
            long interval = paced ? TimeUnit.SECONDS.toNanos(1) / config.rate() : 0;
            long start = System.nanoTime();
            long next = start;
            for (long seq = 1; seq <= config.count(); seq++) {
                long wait = next - System.nanoTime();
                if (paced && wait > 0) {
                    LockSupport.parkNanos(wait);
                }
                if (Thread.currentThread().isInterrupted()) {
                    System.out.println("probe publisher: run=" + run + " stopped at " + (seq - 1));
                    return;
                }
                ProbeEvent e = new ProbeEvent();
                e.run = run;
                e.seq = seq;
                e.sentNanos = System.nanoTime();
                bus.deliver(e);
                next += interval;
            }
            System.out.println("probe publisher: run=" + run + " published=" + config.count() + " startNs=" + start);
        } catch (InterruptedException e) {
            System.out.println("probe publisher: run=" + run + " stopped while waiting for a consumer");
        }
    }

    /** Whether a consumer of probe events became known on this node within the configured time. */
    private static boolean awaitConsumer(ProbePublisherConfig config, BundleContext context)
            throws InterruptedException {
        Filter consumers;
        try {
            consumers = context.createFilter("(" + CONSUMED + "=" + ProbeEvent.class.getName() + ")");
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        ServiceTracker<Object, Object> tracker = new ServiceTracker<>(context, consumers, null);
        tracker.open(true);
        try {
            if (tracker.waitForService(TimeUnit.SECONDS.toMillis(config.consumer_timeout_s())) == null) {
                return false;
            }
        } finally {
            tracker.close();
        }
        System.out.println("probe publisher: run=" + config.run() + " consumer known");
        return true;
    }

    @Deactivate
    void stop() throws InterruptedException {
        thread.interrupt();
        thread.join(TimeUnit.SECONDS.toMillis(10));
    }

}
