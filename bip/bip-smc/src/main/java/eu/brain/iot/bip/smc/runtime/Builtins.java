package eu.brain.iot.bip.smc.runtime;

import java.util.List;

/**
 * The stochastic functions every model may call in simulation, when it declares them as extern functions:
 * {@code extern function int uniform(int lo, int hi)}, {@code extern function float uniformReal(float lo, float hi)},
 * {@code extern function bool bernoulli(float p)}. Deployed code gets them from its extern implementation like
 * any other extern function.
 */
public final class Builtins {

    public static final String DESCRIPTION = "int uniform(int, int), float uniformReal(float, float), "
            + "bool bernoulli(float)";

    private Builtins() {
    }

    /** @return whether a call with this name and these parameter and result types is a built-in */
    public static boolean isBuiltin(String name, List<String> paramTypes, String resultType) {
        return switch (name) {
            case "uniform" -> paramTypes.equals(List.of("int", "int")) && resultType.equals("int");
            case "uniformReal" -> paramTypes.equals(List.of("float", "float")) && resultType.equals("float");
            case "bernoulli" -> paramTypes.equals(List.of("float")) && resultType.equals("bool");
            default -> false;
        };
    }

    /** Calls a built-in, else the model's simulation. */
    public static Object call(String name, List<String> paramTypes, String resultType, Object[] args,
            TraceRandom random, SimulationExterns externs) {
        if (isBuiltin(name, paramTypes, resultType)) {
            return switch (name) {
                case "uniform" -> random.uniform((Integer) args[0], (Integer) args[1]);
                case "uniformReal" -> random.uniformReal(((Number) args[0]).doubleValue(),
                        ((Number) args[1]).doubleValue());
                default -> random.bernoulli(((Number) args[0]).doubleValue());
            };
        }
        return simulate(externs, name, paramTypes, resultType, args, random);
    }

    /**
     * Calls the model's simulation of an extern function (both engines go through here): what it throws, and a
     * result of another type than the model declares, become an {@link ExternSimulationException} naming the
     * function and the class, so a failing trace says whose code to fix.
     */
    public static Object simulate(SimulationExterns externs, String name, List<String> paramTypes, String resultType,
            Object[] args, TraceRandom random) {
        Object result;
        try {
            result = externs.call(name, paramTypes, resultType, args, random);
        } catch (StochasticException e) {
            throw e;
        } catch (RuntimeException | LinkageError e) {
            throw new ExternSimulationException(what(externs, name, paramTypes, resultType) + " threw " + e
                    + "; fix that class (it must answer every call the model makes)", e);
        }
        boolean fits = switch (resultType) {
            case "int" -> result instanceof Integer;
            case "float" -> result instanceof Number;
            case "bool" -> result instanceof Boolean;
            case "string" -> result instanceof String;
            default -> true;
        };
        if (!fits) {
            throw new ExternSimulationException(what(externs, name, paramTypes, resultType) + " answered "
                    + (result == null ? "null" : result + " (" + result.getClass().getName() + ")") + " where the model "
                    + "declares " + resultType + "; fix that class (int: Integer, float: a Number, bool: Boolean, "
                    + "string: String)", null);
        }
        return result;
    }

    private static String what(SimulationExterns externs, String name, List<String> paramTypes, String resultType) {
        return "the simulation of extern function " + (resultType.equals("no value") ? "" : resultType + " ") + name + "(" + String.join(", ", paramTypes)
                + ") in " + (externs == SimulationExterns.NONE ? "no class" : "class " + externs.getClass().getName());
    }
}
