package eu.brain.iot.eventing.api;

import java.util.Map;

import org.osgi.annotation.versioning.ProviderType;

/**
 * The asynchronous event bus of a fabric node.
 * <p>
 * Both methods return as soon as the event is queued for every consumer that takes it; they never wait for a
 * consumer to run. Memory is bounded: when a consumer's queue is full, {@code deliver} waits for room for a
 * configured time and then throws {@link EventBusOverflowException}; in that case the event was queued for no
 * consumer at all, so the caller may retry.
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
}
