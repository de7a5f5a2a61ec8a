package eu.brain.iot.bip.generate;

import java.util.List;

/**
 * Which extern calls the generated simulation answers itself, by a method of the same name on the trace's random
 * source ({@code smc.runtime.TraceRandom}), rather than through the model's simulation of its extern functions. The
 * model checker that runs the simulation says which (its {@code smc.runtime.Builtins}); the generator only writes
 * the calls, so it does not depend on the model checker.
 */
@FunctionalInterface
public interface SimulationBuiltins {

    /** @return whether a call with this name and these parameter and result types (BIP type names) is a built-in */
    boolean isBuiltin(String name, List<String> paramTypes, String resultType);
}
