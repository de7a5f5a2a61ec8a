package eu.brain.iot.bip.smc.sim;

/** A system that cannot be simulated (hierarchical connectors, generated code that does not compile, ...). */
public final class SimulationException extends Exception {
    private static final long serialVersionUID = 1L;

    public SimulationException(String message) {
        super(message);
    }
}
