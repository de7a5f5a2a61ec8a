package eu.brain.iot.eventing.spi;

import java.util.List;
import java.util.Map;

import org.osgi.annotation.versioning.ProviderType;

/**
 * Delivery of events that came from another node of the fabric to this node's behaviours. Registered by the bus.
 * <p>
 * An event delivered here is routed like a local event of its type (consumers of any of {@code typeNames}, filters
 * over the fields), but to local behaviours only: never to an {@link EventForwarder}, so an event crosses at most
 * one hop. An event no local behaviour takes follows the bus's rules for unhandled events (the
 * {@link UnhandledEventPolicy}'s hold, consumers of last resort, or counted as unhandled), and a held one is never
 * handed to a forwarder either.
 * <p>
 * Threading: any thread; never waits.
 */
@ProviderType
public interface RemoteEvents {

    /**
     * Deliver one event from another node if every local behaviour that takes it has room now.
     *
     * @param eventType the fully qualified name of the event's type
     * @param typeNames the type name first, then its supertypes and interfaces as the publishing node knew them
     * @param eventData the event's fields by name (its {@code sourceNode} names the publishing node); copied at once
     * @param done run once every local behaviour that took the event returned from {@code notify} (or failed, or
     *        went away before it was called); run at once when the event was accepted for no behaviour (held for
     *        the unhandled-event policy, given to consumers of last resort, or counted as unhandled). Runs on a
     *        delivery worker: it must be quick and must not block
     * @return {@code true} when accepted; {@code false} when a behaviour's queue (or the hold) was full: nothing was
     *         queued and {@code done} will not run; offer the event again later
     */
    boolean tryDeliverRemote(String eventType, List<String> typeNames, Map<String, Object> eventData, Runnable done);

    /**
     * As {@link #tryDeliverRemote}, but an event that no local behaviour takes now is not accepted either
     * ({@code false}: offer it again later): for a node whose behaviours are still coming up (restored from its
     * installer's journal, installed from its configuration folder), which events sent to it before it stopped may
     * reach first. Since 1.2.
     */
    boolean tryDeliverRemoteToBehaviours(String eventType, List<String> typeNames, Map<String, Object> eventData,
            Runnable done);
}
