package eu.brain.iot.bip.smc.engine;

/** A trace failed: an exception in the model's code (division by zero, ...) or a stochastic function misused. */
public final class TraceFailureException extends Exception {
    private static final long serialVersionUID = 1L;

    public TraceFailureException(String message, Throwable cause) {
        super(message, cause);
    }
}
