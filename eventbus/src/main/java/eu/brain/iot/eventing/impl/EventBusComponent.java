package eu.brain.iot.eventing.impl;

import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.Filter;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.ComponentServiceObjects;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.metatype.annotations.Designate;

import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;
import eu.brain.iot.eventing.spi.EventForwarder;
import eu.brain.iot.eventing.spi.HeldEvents;
import eu.brain.iot.eventing.spi.HeldType;
import eu.brain.iot.eventing.spi.RemoteEvents;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;

/**
 * The event bus as a Declarative Services component: publishes {@link EventBus}, {@link EventBusStatistics} and
 * {@link HeldEvents}, follows the smart behaviour whiteboard and the highest-ranked {@link UnhandledEventPolicy}.
 * Behaviours and the policy come and go at any time, hence dynamic references with bind methods (constructor
 * injection cannot follow them); everything else arrives through the constructor. A configuration change is
 * applied in place ({@link #modified}): the bus, its queues and its hold stay, so no queued event is lost to it.
 */
@Component(service = { EventBus.class, EventBusStatistics.class, HeldEvents.class, RemoteEvents.class },
        configurationPid = BusConfig.PID, configurationPolicy = ConfigurationPolicy.OPTIONAL)
@Designate(ocd = BusConfig.class)
public final class EventBusComponent implements EventBus, EventBusStatistics, HeldEvents, RemoteEvents {

    /** How long a delivery worker beyond {@code delivery.workers} (added for a stalled behaviour) stays idle. */
    static final long WORKER_KEEP_ALIVE_NANOS = TimeUnit.SECONDS.toNanos(1);

    private final AsyncEventBus bus;
    private final Logger log;

    @Activate
    public EventBusComponent(BundleContext context, BusConfig config,
            @Reference(service = LoggerFactory.class) Logger log) {
        this.log = log;
        DeliveryPool.Settings delivery = deliverySettings(config, Runtime.getRuntime().availableProcessors());
        this.bus = new AsyncEventBus(context.getProperty(Constants.FRAMEWORK_UUID), config.queue_capacity(),
                config.overflow_timeout_ms(), delivery, log);
    }

    static DeliveryPool.Settings deliverySettings(BusConfig config, int processors) {
        // At least 2 by default, also on one core: then a single behaviour blocked in notify() never holds up the
        // others, not even for the stall threshold the watchdog needs to notice it.
        int workers = config.delivery_workers() > 0 ? config.delivery_workers()
                : Math.max(2, processors);
        return new DeliveryPool.Settings(workers, TimeUnit.MICROSECONDS.toNanos(config.idle_spin_us()),
                TimeUnit.MILLISECONDS.toNanos(Math.max(1, config.stall_threshold_ms())), WORKER_KEEP_ALIVE_NANOS,
                TimeUnit.MILLISECONDS.toNanos(Math.max(1, config.stall_warning_ms())));
    }

    @Modified
    void modified(BusConfig config) {
        try {
            bus.reconfigure(config.queue_capacity(), config.overflow_timeout_ms(),
                    deliverySettings(config, Runtime.getRuntime().availableProcessors()));
        } catch (IllegalArgumentException e) {
            log.error("The event bus configuration (PID {}) was not applied: {}. The previous settings stay; fix "
                    + "the configuration.", BusConfig.PID, e.getMessage());
        }
    }

    @Deactivate
    void deactivate() {
        bus.close();
    }

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY, unbind = "unsetUnhandledEventPolicy")
    void setUnhandledEventPolicy(UnhandledEventPolicy policy) {
        bus.policy(policy);
        log.info("Unhandled events are now put to the policy {}", policy.getClass().getName());
    }

    void unsetUnhandledEventPolicy(UnhandledEventPolicy policy) {
        bus.policyGone(policy);
    }

    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC,
            unbind = "removeSmartBehaviour")
    void addSmartBehaviour(ComponentServiceObjects<SmartBehaviour<BrainIoTEvent>> behaviour) {
        add(behaviour, false);
    }

    void removeSmartBehaviour(ServiceReference<?> ref) {
        bus.removeConsumer(serviceId(ref));
    }

    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC,
            unbind = "removeUntypedSmartBehaviour")
    void addUntypedSmartBehaviour(ComponentServiceObjects<UntypedSmartBehaviour> behaviour) {
        add(behaviour, true);
    }

    void removeUntypedSmartBehaviour(ServiceReference<?> ref) {
        bus.removeConsumer(serviceId(ref));
    }

    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC,
            unbind = "removeEventForwarder")
    void addEventForwarder(ComponentServiceObjects<EventForwarder> forwarder) {
        ServiceReference<EventForwarder> ref = forwarder.getServiceReference();
        Object destination = ref.getProperty(EventForwarder.DESTINATION_PROPERTY);
        Set<String> consumed = new LinkedHashSet<>(strings(ref.getProperty(SmartBehaviourNamespace.CONSUMED_PROPERTY)));
        Bundle bundle = ref.getBundle();
        String bundleName = bundle == null ? "?" : bundle.getSymbolicName();
        if (!(destination instanceof String node) || node.isBlank() || consumed.isEmpty()) {
            log.error("Event forwarder {} (bundle {}) names no destination ({}) or no consumed types; it gets no "
                    + "events.", serviceId(ref), bundleName, EventForwarder.DESTINATION_PROPERTY);
            return;
        }
        Filter filter = null;
        Object filterText = ref.getProperty(SmartBehaviourNamespace.FILTER_PROPERTY);
        if (filterText instanceof String text && !text.isBlank()) {
            try {
                filter = FrameworkUtil.createFilter(text);
            } catch (InvalidSyntaxException e) {
                log.error("Event forwarder to {} has an invalid filter \"{}\": {}; it gets no events.", node, text,
                        e.getMessage());
                return;
            }
        }
        bus.addConsumer(new ConsumerSpec(serviceId(ref), "fabric:" + node + "#" + serviceId(ref), bundleName,
                Set.copyOf(consumed), filter, false, true, handle(forwarder), className -> null, node));
    }

    void removeEventForwarder(ServiceReference<?> ref) {
        bus.removeConsumer(serviceId(ref));
    }

    private <S> void add(ComponentServiceObjects<S> behaviour, boolean untyped) {
        ServiceReference<S> ref = behaviour.getServiceReference();
        Bundle bundle = ref.getBundle();
        String bundleName = bundle == null ? "?" : bundle.getSymbolicName();
        String name = describe(ref, bundleName);
        Set<String> consumed = new LinkedHashSet<>(strings(ref.getProperty(SmartBehaviourNamespace.CONSUMED_PROPERTY)));
        boolean lastResort = Boolean.parseBoolean(String.valueOf(ref.getProperty(SmartBehaviourNamespace.LAST_RESORT_PROPERTY)));
        if (lastResort && !untyped) {
            log.error("Smart behaviour {} (bundle {}) is marked consumer of last resort but is not an "
                    + "UntypedSmartBehaviour; it gets no events. Implement UntypedSmartBehaviour.", name, bundleName);
            return;
        }
        if (!lastResort && consumed.isEmpty()) {
            log.error("Smart behaviour {} (bundle {}) declares no consumed event types; it gets no events. "
                    + "Annotate it with @SmartBehaviourDefinition(consumed = ...).", name, bundleName);
            return;
        }
        Filter filter = null;
        Object filterText = ref.getProperty(SmartBehaviourNamespace.FILTER_PROPERTY);
        if (filterText instanceof String text && !text.isBlank()) {
            try {
                filter = FrameworkUtil.createFilter(text);
            } catch (InvalidSyntaxException e) {
                log.error("Smart behaviour {} (bundle {}) has an invalid filter \"{}\": {}; it gets no events "
                        + "until the filter is fixed.", name, bundleName, text, e.getMessage());
                return;
            }
        }
        bus.addConsumer(new ConsumerSpec(serviceId(ref), name, bundleName, Set.copyOf(consumed), filter, lastResort,
                untyped, handle(behaviour), className -> loadClass(bundle, className)));
        log.debug("Smart behaviour {} (bundle {}) consumes {}", name, bundleName, lastResort ? "unhandled events" : consumed);
    }

    private static <S> BehaviourHandle handle(ComponentServiceObjects<S> objects) {
        return new BehaviourHandle() {
            private S service;

            @Override
            public Object get() {
                try {
                    service = objects.getService();
                } catch (IllegalStateException gone) {
                    service = null;
                }
                return service;
            }

            @Override
            public void release() {
                try {
                    objects.ungetService(service);
                } catch (IllegalStateException | IllegalArgumentException gone) {
                    // the component is already deactivated
                }
            }
        };
    }

    private static Class<?> loadClass(Bundle bundle, String className) {
        try {
            return bundle == null ? null : bundle.loadClass(className);
        } catch (ClassNotFoundException | IllegalStateException e) {
            return null;
        }
    }

    private static String describe(ServiceReference<?> ref, String bundleName) {
        Object name = ref.getProperty(SmartBehaviourNamespace.PROPERTY_PREFIX + SmartBehaviourNamespace.NAME);
        if (!(name instanceof String s) || s.isBlank()) {
            name = ref.getProperty("component.name");
        }
        if (!(name instanceof String s2) || s2.isBlank()) {
            name = bundleName;
        }
        return name + "#" + serviceId(ref);
    }

    private static long serviceId(ServiceReference<?> ref) {
        return (Long) ref.getProperty(Constants.SERVICE_ID);
    }

    private static List<String> strings(Object value) {
        if (value instanceof String s) {
            return List.of(s);
        }
        if (value instanceof String[] a) {
            return Arrays.asList(a);
        }
        if (value instanceof java.util.Collection<?> c) {
            return c.stream().map(String::valueOf).toList();
        }
        return List.of();
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

    @Override
    public List<EventTypeStatistics> eventTypes() {
        return bus.eventTypes();
    }

    @Override
    public List<ConsumerStatistics> consumers() {
        return bus.consumers();
    }

    @Override
    public List<HeldType> held() {
        return bus.held();
    }

    @Override
    public int discard(String eventType, String reason) {
        return bus.discard(eventType, reason);
    }
}
