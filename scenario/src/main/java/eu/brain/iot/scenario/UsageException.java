package eu.brain.iot.scenario;

/** A bad command line: the message says what was wrong and what to write instead (exit code 2). */
final class UsageException extends Exception {
    private static final long serialVersionUID = 1L;

    UsageException(String message) {
        super(message);
    }
}
