package eu.brain.iot.eventing.spi;

import java.util.List;
import java.util.Map;

import org.osgi.annotation.versioning.ConsumerType;

/**
 * A consumer that carries events to another node of the fabric on behalf of the behaviours that run there.
 * Registered as an OSGi service by a federation module, one service per remote interest (one set of consumed types
 * and one filter), with the same service properties as a smart behaviour ({@code eu.brain.iot.behaviour.consumed},
 * {@code eu.brain.iot.behaviour.filter}) plus {@link #DESTINATION_PROPERTY}.
 * <p>
 * The bus routes events to a forwarder exactly as to a local behaviour (supertypes and interfaces of typed events,
 * the exact name of untyped ones, the LDAP filter over the fields), through a bounded queue of its own: a full
 * forwarder queue makes {@code deliver} wait and {@code tryDeliver} refuse, as a full behaviour queue does. An event
 * that several forwarders of one destination take goes to only one of them: a node receives each event once. Events
 * that came from another node ({@link RemoteEvents}) never reach a forwarder.
 * <p>
 * Threading: {@link #forward} is called on a delivery worker of the bus, one event at a time per forwarder, in
 * publish order (per publishing thread); it may block to push back (the bus then adds workers for other consumers).
 */
@ConsumerType
public interface EventForwarder {

    /** Service property ({@code String}): the name of the node the forwarder carries events to. */
    String DESTINATION_PROPERTY = "eu.brain.iot.fabric.destination";

    /**
     * Carry one event.
     *
     * @param eventType the fully qualified name of the event's type
     * @param typeNames the type name first, then (for a typed event) its superclasses and interfaces, as the bus
     *        matched consumers; the receiving node routes with the same list
     * @param properties the event's fields by name, as an untyped behaviour gets them; owned by the forwarder
     */
    void forward(String eventType, List<String> typeNames, Map<String, Object> properties);
}
