package eu.brain.iot.robotsim.cli;

/** A command line that cannot be used; the message is one line saying what is wrong. */
public final class UsageException extends Exception {
    private static final long serialVersionUID = 1L;

    public UsageException(String message) {
        super(message);
    }
}
