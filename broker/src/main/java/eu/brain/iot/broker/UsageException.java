package eu.brain.iot.broker;

/** A command line the broker cannot run with; its message says which flag and what it needs. */
public final class UsageException extends Exception {
    private static final long serialVersionUID = 1L;

    public UsageException(String message) {
        super(message);
    }
}
