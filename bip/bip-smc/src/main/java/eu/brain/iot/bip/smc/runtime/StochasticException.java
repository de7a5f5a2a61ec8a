package eu.brain.iot.bip.smc.runtime;

/** A stochastic function was called with arguments outside its domain, or an extern has no simulation. */
public final class StochasticException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public StochasticException(String message) {
        super(message);
    }
}
