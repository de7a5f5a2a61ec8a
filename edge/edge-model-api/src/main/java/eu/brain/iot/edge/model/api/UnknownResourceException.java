package eu.brain.iot.edge.model.api;

/** A provider, service, resource or action that the model does not have; the message says which and what exists. */
public class UnknownResourceException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public UnknownResourceException(String message) {
        super(message);
    }
}
