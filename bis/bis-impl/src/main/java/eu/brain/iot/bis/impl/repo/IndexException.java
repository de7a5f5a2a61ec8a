package eu.brain.iot.bis.impl.repo;

/** An index that cannot be used: unreadable, malformed or not trusted. The message is for people. */
public final class IndexException extends Exception {
    private static final long serialVersionUID = 1L;

    public IndexException(String message) {
        super(message);
    }
}
