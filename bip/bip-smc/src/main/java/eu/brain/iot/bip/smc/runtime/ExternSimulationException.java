package eu.brain.iot.bip.smc.runtime;

/**
 * The simulation of an extern function (the model's {@link SimulationExterns} class) failed: it threw, or answered a
 * value of another type than the model declares. The message names the function and the class.
 */
public final class ExternSimulationException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public ExternSimulationException(String message, Throwable cause) {
        super(message, cause);
    }
}
