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
     *        delivery worker, or on the calling thread when run at once: it must be quick and must not block
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

    /**
     * Publish again, as if published here now, an event this node published before for a node of the fabric that
     * never took it (it stayed offline and the fabric gave it up), but only to the consumers that cannot have taken it
     * then: those registered after {@code publishedMillis}, local behaviours and forwarders to other nodes alike (a
     * behaviour installed since, a node whose interest came since). When nothing consumes it at all, it follows the
     * rules for unhandled events (the policy's hold: the BMS installs a behaviour for it). Routed by {@code typeNames}
     * as an event from another node is. Never waits. Since 1.5.
     *
     * @param publishedMillis when it was first published (epoch milliseconds)
     * @return {@code false} when a queue (or the hold) was full: nothing was queued, offer it again later; {@code true}
     *         otherwise, also when every consumer it has was there before (nothing to do)
     */
    boolean tryDeliverGivenUp(String eventType, List<String> typeNames, Map<String, Object> eventData,
            long publishedMillis);
}
