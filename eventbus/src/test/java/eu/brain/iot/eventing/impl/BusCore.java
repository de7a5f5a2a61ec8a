package eu.brain.iot.eventing.impl;

import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import org.osgi.framework.Filter;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.service.log.Logger;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;
import eu.brain.iot.eventing.spi.HeldEvents;
import eu.brain.iot.eventing.spi.HeldType;
import eu.brain.iot.eventing.spi.RemoteEvents;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;

/**
 * The real bus core (package-private in the bus bundle) for other modules' unit tests (the BMS's): the same class, on
 * the test's class path, without OSGi. It is shipped in this module's test-support jar only (classifier
 * {@code bus-core}, see pom.xml), never in a bundle; it lives here, beside the core it wraps, so that a change of the
 * core is compiled against it in the bus's own build.
 */
public final class BusCore implements EventBus, HeldEvents, RemoteEvents {

    private final AsyncEventBus bus;
    private final AtomicLong ids = new AtomicLong();

    public BusCore(int queueCapacity, long overflowTimeoutMillis, Logger log) {
        bus = new AsyncEventBus("test-node", queueCapacity, overflowTimeoutMillis, new DeliveryPool.Settings(2,
                TimeUnit.MICROSECONDS.toNanos(50), TimeUnit.MILLISECONDS.toNanos(5), TimeUnit.SECONDS.toNanos(1)),
                log);
    }

    /** Register a typed behaviour, as the bus's component does when its service appears. */
    public long addBehaviour(Object behaviour, String... consumed) {
        long id = ids.incrementAndGet();
        bus.addConsumer(new ConsumerSpec(id, "behaviour#" + id, "test.bundle", Set.of(consumed), null, false, false,
                BehaviourHandle.of(behaviour), className -> null));
        return id;
    }

    /**
     * Register a typed behaviour with a filter over the fields ({@code null} for none) that loads event classes by
     * name from its own class loader, as a behaviour's bundle does.
     */
    public long addTypedBehaviour(Object behaviour, String filter, String... consumed) {
        long id = ids.incrementAndGet();
        ClassLoader loader = behaviour.getClass().getClassLoader();
        bus.addConsumer(new ConsumerSpec(id, "typed#" + id, "test.bundle", Set.of(consumed), filter(filter), false,
                false, BehaviourHandle.of(behaviour), className -> {
                    try {
                        return Class.forName(className, false, loader);
                    } catch (ClassNotFoundException e) {
                        return null;
                    }
                }));
        return id;
    }

    /** Register an untyped behaviour with a filter over the fields ({@code null} for none). */
    public long addUntypedBehaviour(Object behaviour, String filter, String... consumed) {
        long id = ids.incrementAndGet();
        bus.addConsumer(new ConsumerSpec(id, "untyped#" + id, "test.bundle", Set.of(consumed), filter(filter), false,
                true, BehaviourHandle.of(behaviour), className -> null));
        return id;
    }

    /** Register an event forwarder to another node, as the bus's component does when its service appears. */
    public long addForwarder(Object forwarder, String destination, String filter, String... consumed) {
        long id = ids.incrementAndGet();
        bus.addConsumer(new ConsumerSpec(id, "fabric:" + destination + "#" + id, "test.bundle", Set.of(consumed),
                filter(filter), false, true, BehaviourHandle.of(forwarder), className -> null, destination));
        return id;
    }

    private static Filter filter(String text) {
        try {
            return text == null || text.isBlank() ? null : FrameworkUtil.createFilter(text);
        } catch (InvalidSyntaxException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    @Override
    public boolean tryDeliverRemote(String eventType, List<String> typeNames, Map<String, Object> eventData,
            Runnable done) {
        return bus.publishRemote(eventType, typeNames, eventData, done, false);
    }

    @Override
    public boolean tryDeliverGivenUp(String eventType, List<String> typeNames, Map<String, Object> eventData,
            long publishedMillis) {
        return GivenUp.publish(bus, eventType, typeNames, eventData, publishedMillis);
    }

    @Override
    public boolean tryDeliverRemoteToBehaviours(String eventType, List<String> typeNames,
            Map<String, Object> eventData, Runnable done) {
        return bus.publishRemote(eventType, typeNames, eventData, done, true);
    }

    public void removeBehaviour(long id) {
        bus.removeConsumer(id);
    }

    public void policy(UnhandledEventPolicy policy) {
        bus.policy(policy);
    }

    @Override
    public void deliver(BrainIoTEvent event) {
        bus.deliver(event);
    }

    @Override
    public void deliver(String eventType, Map<String, Object> eventData) {
        bus.deliver(eventType, eventData);
    }

    @Override
    public boolean tryDeliver(BrainIoTEvent event) {
        return bus.tryDeliver(event);
    }

    @Override
    public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
        return bus.tryDeliver(eventType, eventData);
    }

    @Override
    public List<HeldType> held() {
        return bus.held();
    }

    @Override
    public int discard(String eventType, String reason) {
        return bus.discard(eventType, reason);
    }

    public EventTypeStatistics statistics(String eventType) {
        return bus.eventTypes().stream().filter(s -> s.eventType.equals(eventType)).findFirst()
                .orElseGet(EventTypeStatistics::new);
    }

    /** How many events wait in the queue of a behaviour or forwarder (0 once it is gone). */
    public int queueDepth(long id) {
        return bus.consumers().stream().filter(c -> c.serviceId == id).mapToInt(c -> c.queueDepth).findFirst()
                .orElse(0);
    }

    public void close() {
        bus.close();
    }
}
