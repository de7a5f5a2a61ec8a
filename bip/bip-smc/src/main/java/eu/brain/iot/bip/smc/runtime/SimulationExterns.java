package eu.brain.iot.bip.smc.runtime;

import java.util.List;

/**
 * The simulation of a model's extern functions for statistical model checking: a model names its class beside the
 * model (the requirements file's {@code set externs = com.example.MyExterns}, the CLI's {@code --externs}); the class
 * has a public no-argument constructor. One instance per sampling thread, so it may keep state between calls, but
 * must draw every random value from {@code random} (a trace must be a function of its seed). The built-in functions
 * ({@link Builtins}) never reach it.
 */
@FunctionalInterface
public interface SimulationExterns {

    /**
     * @param name the function name (qualifier dropped)
     * @param paramTypes the declared parameter types, e.g. ["int", "float"]
     * @param resultType the declared result type ("no value" for none)
     * @param args the arguments (Integer, Double, Boolean, String or extern objects)
     * @param random the trace's random source
     * @return the result (Integer, Double, Boolean, String, ...; null for functions without one)
     */
    Object call(String name, List<String> paramTypes, String resultType, Object[] args, TraceRandom random);

    /** No simulation given: any extern function other than the built-ins is an error. */
    SimulationExterns NONE = (name, types, result, args, random) -> {
        throw new StochasticException("extern function " + name + types + " has no simulation: give one with "
                + "'set externs = CLASS' (requirements file) or --externs CLASS, or use a built-in ("
                + Builtins.DESCRIPTION + ")");
    };
}
