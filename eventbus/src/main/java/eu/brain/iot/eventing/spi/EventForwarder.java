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
 * Threading: one event at a time per forwarder, in publish order (per publishing thread). The publisher whose
 * event finds the forwarder idle offers it (and any queued behind it) on its own thread through {@link #forwardNow},
 * which must not wait; what that refuses, and what a busy forwarder's queue holds, {@link #forward} gets on a
 * delivery worker of the bus, where it may block to push back (the bus then adds workers for other consumers). An
 * event on its way to another node then costs no worker's wake-up, the largest share of its latency on a busy node.
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

    /**
     * Carry one event if that needs no waiting (room in the hand-off to the network, nothing to open); called on the
     * publisher's thread, outside the bus's locks, where the caller may hold locks of its own: it must neither block
     * nor call the bus. Since 1.4.
     *
     * @param eventType as for {@link #forward}
     * @param typeNames as for {@link #forward}
     * @param properties as for {@link #forward}; owned by the forwarder only when it returns {@code true}
     * @return {@code true} when the event was taken; {@code false} when it was not (nothing kept): the bus then hands
     *         it to {@link #forward} on a delivery worker. The default takes none
     */
    default boolean forwardNow(String eventType, List<String> typeNames, Map<String, Object> properties) {
        return false;
    }
}
