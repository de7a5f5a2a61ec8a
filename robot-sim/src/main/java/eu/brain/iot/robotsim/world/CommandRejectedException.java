package eu.brain.iot.robotsim.world;

/** A command the world refused; it changed nothing. */
public final class CommandRejectedException extends Exception {
    private static final long serialVersionUID = 1L;

    /** Why: the HTTP layer maps NOT_FOUND to 404, UNPROCESSABLE to 422 and LIMIT (a full queue) to 429. */
    public enum Kind { NOT_FOUND, UNPROCESSABLE, LIMIT }

    private final Kind kind;
    private final String field;

    public CommandRejectedException(Kind kind, String field, String message) {
        super(message);
        this.kind = kind;
        this.field = field;
    }

    public Kind kind() {
        return kind;
    }

    /** The request field at fault, or null. */
    public String field() {
        return field;
    }
}
