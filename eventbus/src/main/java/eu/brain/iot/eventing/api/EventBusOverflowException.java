package eu.brain.iot.eventing.api;

/**
 * Thrown by {@link EventBus#deliver} when a consumer's bounded queue stayed full for longer than the bus's
 * configured overflow timeout. The event was delivered to no consumer; the publisher decides whether to retry,
 * slow down or report the failure.
 */
public class EventBusOverflowException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final String eventType;
    private final String consumer;

    public EventBusOverflowException(String eventType, String consumer, String message) {
        super(message);
        this.eventType = eventType;
        this.consumer = consumer;
    }

    /** @return the type of the event that could not be queued */
    public String getEventType() {
        return eventType;
    }

    /** @return a description of the consumer whose queue was full */
    public String getConsumer() {
        return consumer;
    }
}
