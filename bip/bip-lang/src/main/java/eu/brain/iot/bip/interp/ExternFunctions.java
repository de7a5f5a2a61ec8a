package eu.brain.iot.bip.interp;

import java.util.List;

/** What interpreted models call for their extern functions (a model checker plugs in its stochastic stand-ins). */
@FunctionalInterface
public interface ExternFunctions {

    /**
     * @param name the function name (qualifier dropped)
     * @param paramTypes the declared parameter types, e.g. ["int", "float"]
     * @param resultType the declared result type ("no value" for none)
     * @param args the arguments, converted to those types (Integer, Double, Boolean, String or extern objects)
     * @return the result (null for functions without one)
     */
    Object call(String name, List<String> paramTypes, String resultType, Object[] args);

    ExternFunctions NONE = (name, types, result, args) -> {
        throw new IllegalStateException("extern function " + name + " has no implementation here");
    };
}
