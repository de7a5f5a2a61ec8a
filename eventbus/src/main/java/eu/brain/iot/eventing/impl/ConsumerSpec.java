package eu.brain.iot.eventing.impl;

import java.util.Set;
import java.util.function.Function;

import org.osgi.framework.Filter;

/**
 * A registered behaviour as the bus sees it.
 *
 * @param serviceId the behaviour service's id
 * @param name a readable name for logs and statistics
 * @param bundle the symbolic name of the registering bundle
 * @param consumed the consumed event type names (empty for a consumer of last resort)
 * @param filter the filter over event fields, or {@code null}
 * @param lastResort whether it only receives events no one else consumes
 * @param untyped whether it was registered as an {@code UntypedSmartBehaviour} (an object may implement both)
 * @param target the {@code SmartBehaviour} or {@code UntypedSmartBehaviour} object, fetched on first delivery
 * @param classes loads a class by name as the behaviour's bundle sees it; {@code null} when it cannot
 * @param forwardTo for an {@link eu.brain.iot.eventing.spi.EventForwarder}, the node it carries events to;
 *        {@code null} for a behaviour
 */
record ConsumerSpec(long serviceId, String name, String bundle, Set<String> consumed, Filter filter,
        boolean lastResort, boolean untyped, BehaviourHandle target, Function<String, Class<?>> classes,
        String forwardTo) {

    /** A local behaviour. */
    ConsumerSpec(long serviceId, String name, String bundle, Set<String> consumed, Filter filter, boolean lastResort,
            boolean untyped, BehaviourHandle target, Function<String, Class<?>> classes) {
        this(serviceId, name, bundle, consumed, filter, lastResort, untyped, target, classes, null);
    }

    /** @return whether this consumer carries events to another node */
    boolean forwarder() {
        return forwardTo != null;
    }
}
