package eu.brain.iot.eventing.api;

import java.util.Map;

import org.osgi.annotation.versioning.ProviderType;

/**
 * The asynchronous event bus of a fabric node.
 * <p>
 * Every method returns as soon as the event is queued for every consumer that takes it; none waits for a
 * consumer to run. Memory is bounded: each consumer has a bounded queue. When one that an event goes to is full,
 * the two kinds of publishing differ:
 * <ul>
 * <li>{@code deliver} waits for room for a configured time ({@code overflow.timeout.ms}) and then throws
 * {@link EventBusOverflowException}: for publishers that may be slowed down, such as a person at a shell or a
 * behaviour, whose waiting is the back-pressure;</li>
 * <li>{@code tryDeliver} (since 1.2) never waits: it returns {@code false} at once. For publishers that must not be
 * held up, such as a gateway polling a fleet on one thread: such a publisher keeps the event and decides what to do
 * (retry it later, in order; replace it by a newer state of the same thing; report it), but never drops it
 * silently.</li>
 * </ul>
 * In both cases an event that was refused was queued for no consumer at all (all or none), so retrying it cannot
 * deliver it twice.
 */
@ProviderType
public interface EventBus {

    /**
     * Publish a typed event. The bus copies it at once; the caller may reuse the object afterwards.
     *
     * @param event the event; {@code sourceNode} and {@code timestamp} are filled in when {@code null}
     * @throws EventBusOverflowException if a consumer's queue stayed full for the configured time
     * @throws IllegalArgumentException if {@code event} is {@code null}
     */
    void deliver(BrainIoTEvent event);

    /**
     * Publish an untyped event, for publishers that do not have the event's class.
     *
     * @param eventType the fully qualified name of the event's type
     * @param eventData the event's fields by name; copied at once
     * @throws EventBusOverflowException if a consumer's queue stayed full for the configured time
     * @throws IllegalArgumentException if an argument is {@code null}
     */
    void deliver(String eventType, Map<String, Object> eventData);

    /**
     * Publish a typed event if every consumer that takes it has room now; never waits. Like
     * {@link #deliver(BrainIoTEvent)} in everything else: the bus copies the event at once, an event that no
     * consumer takes is handled as there (held for an unhandled-event policy, given to consumers of last resort,
     * or counted as unhandled) and counts as accepted.
     *
     * @param event the event; {@code sourceNode} and {@code timestamp} are filled in when {@code null}
     * @return {@code true} when the bus accepted the event; {@code false} when a consumer's queue (or the bus's
     *         hold of unhandled events) was full: the event was then queued for no consumer, and stays the caller's
     *         to publish again later
     * @throws IllegalArgumentException if {@code event} is {@code null}
     * @since 1.2
     */
    boolean tryDeliver(BrainIoTEvent event);

    /**
     * Publish an untyped event if every consumer that takes it has room now; never waits. See
     * {@link #tryDeliver(BrainIoTEvent)}.
     *
     * @param eventType the fully qualified name of the event's type
     * @param eventData the event's fields by name; copied at once
     * @return {@code true} when accepted; {@code false} when a queue was full (queued for no consumer)
     * @throws IllegalArgumentException if an argument is {@code null}
     * @since 1.2
     */
    boolean tryDeliver(String eventType, Map<String, Object> eventData);
}
