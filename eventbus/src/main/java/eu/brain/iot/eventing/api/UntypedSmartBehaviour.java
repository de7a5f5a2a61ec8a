package eu.brain.iot.eventing.api;

import java.util.Map;

import org.osgi.annotation.versioning.ConsumerType;

/**
 * A behaviour that consumes events as maps of their fields, without compiling against their classes.
 * Register it as an OSGi service with {@link eu.brain.iot.eventing.annotation.SmartBehaviourDefinition}
 * (consumed event type names) or with {@link eu.brain.iot.eventing.annotation.ConsumerOfLastResort} to receive
 * only events that no other behaviour consumes.
 */
@ConsumerType
public interface UntypedSmartBehaviour {

    /**
     * Receive one event.
     *
     * @param eventType the fully qualified name of the event's type
     * @param properties the event's fields by name; nested data objects appear as maps, arrays and collections
     *        as lists. The map belongs to this behaviour alone.
     */
    void notify(String eventType, Map<String, ?> properties);
}
