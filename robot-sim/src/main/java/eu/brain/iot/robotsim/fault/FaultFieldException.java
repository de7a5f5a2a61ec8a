package eu.brain.iot.robotsim.fault;

/** A fault setting that cannot be accepted; names the field. */
public final class FaultFieldException extends Exception {
    private static final long serialVersionUID = 1L;
    private final String field;

    public FaultFieldException(String field, String message) {
        super(message);
        this.field = field;
    }

    public String field() {
        return field;
    }
}
