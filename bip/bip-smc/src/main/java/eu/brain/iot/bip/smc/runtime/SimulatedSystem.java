package eu.brain.iot.bip.smc.runtime;

/**
 * One system being simulated, trace after trace, by the statistical model checker: the compiled driver generated
 * for a system (see {@code generate.SimulationWriter}) and the interpreter ({@code smc.sim.InterpretedSystem})
 * implement it with the same semantics and the same random draws. Owned by one sampling thread.
 */
public interface SimulatedSystem {

    /** Starts a new trace: reseeds, creates every atom and runs the initial transitions (state 0). */
    void reset(long seed);

    /**
     * Takes one step: among the enabled candidates (each atom's internal step, each enabled port that is not
     * exported, each enabled maximal interaction of each connector, in that order), one chosen uniformly.
     *
     * @return false at a deadlock (no candidate; the state does not change)
     */
    boolean step();

    /** @return the value of atomic proposition {@code index} of the compiled query in the current state */
    boolean ap(int index);

    /** @return what the last step executed ({@code "internal A"}, {@code "A.p"}, {@code "k: [A.p, B.q]"}) */
    String lastStep();

    /** @return the state of every atom, {@code path [places] {data}} per line, for tests and traces */
    String state();
}
