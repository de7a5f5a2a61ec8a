package eu.brain.iot.bip.interp;

import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.check.Values;
import eu.brain.iot.bip.model.Expr.BinaryOp;
import eu.brain.iot.bip.model.Expr.UnaryOp;

/**
 * The interpreter's operators on run-time values: exactly {@link Values} (32-bit wrapping {@code int}, {@code double},
 * Java string concatenation). The semantics lives in {@code check} because the checker folds constants with it;
 * keeping it there is what lets {@code interp} depend on {@code check} and never the other way round.
 */
public final class Ops {

    private Ops() {
    }

    public static Object unary(UnaryOp op, Object v) {
        return Values.unary(op, v);
    }

    /** Binary operators other than the short-circuit {@code &&} and {@code ||}. */
    public static Object binary(BinaryOp op, Object l, Object r) {
        return Values.binary(op, l, r);
    }

    /** Converts a value for storage in data of a declared type (an int stored in a float becomes a double). */
    public static Object coerce(Object value, Type type) {
        return Values.coerce(value, type);
    }

    /** @return the value a datum of this type holds before anything is assigned (Java's field defaults) */
    public static Object defaultValue(Type type) {
        return Values.defaultValue(type);
    }
}
