package eu.brain.iot.bip.check;

import java.util.Objects;

import eu.brain.iot.bip.model.Expr.BinaryOp;
import eu.brain.iot.bip.model.Expr.UnaryOp;

/**
 * The language's value semantics, shared by the checker's constant folding and the interpreter ({@code interp.Ops}
 * delegates here): the operators on run-time values, with exactly the semantics of the Java the generator writes:
 * {@code int} is a 32-bit {@link Integer} that wraps, {@code float}/{@code double} a {@link Double}, mixed
 * arithmetic promotes to double, {@code +} with a string concatenates as Java does, {@code ==} on strings compares
 * contents.
 */
public final class Values {

    private Values() {
    }

    public static Object unary(UnaryOp op, Object v) {
        return switch (op) {
            case NOT -> !(Boolean) v;
            case NEG -> v instanceof Integer i ? (Object) (-i) : (Object) (-(Double) v);
            case PLUS -> v;
            case BIT_NOT -> ~(Integer) v;
        };
    }

    /** Binary operators other than the short-circuit {@code &&} and {@code ||}. */
    public static Object binary(BinaryOp op, Object l, Object r) {
        if (op == BinaryOp.ADD && (l instanceof String || r instanceof String)) {
            return String.valueOf(l) + r;
        }
        if (op == BinaryOp.EQ || op == BinaryOp.NE) {
            boolean equal = l instanceof Number a && r instanceof Number b
                    ? (l instanceof Integer && r instanceof Integer ? a.intValue() == b.intValue()
                            : a.doubleValue() == b.doubleValue())
                    : Objects.equals(l, r);
            return op == BinaryOp.EQ ? equal : !equal;
        }
        if (op.bitwise()) {
            if (l instanceof Boolean a && r instanceof Boolean b) {
                return switch (op) {
                    case BIT_AND -> a & b;
                    case BIT_OR -> a | b;
                    default -> a ^ b;
                };
            }
            int a = (Integer) l;
            int b = (Integer) r;
            return switch (op) {
                case BIT_AND -> a & b;
                case BIT_OR -> a | b;
                default -> a ^ b;
            };
        }
        if (l instanceof Integer a && r instanceof Integer b) {
            return switch (op) {
                case ADD -> a + b;
                case SUB -> a - b;
                case MUL -> a * b;
                case DIV -> a / b;
                case MOD -> a % b;
                case LT -> a < b;
                case LE -> a <= b;
                case GT -> a > b;
                case GE -> a >= b;
                default -> throw new IllegalArgumentException("operator " + op.symbol + " on ints");
            };
        }
        double a = ((Number) l).doubleValue();
        double b = ((Number) r).doubleValue();
        return switch (op) {
            case ADD -> a + b;
            case SUB -> a - b;
            case MUL -> a * b;
            case DIV -> a / b;
            case MOD -> a % b;
            case LT -> a < b;
            case LE -> a <= b;
            case GT -> a > b;
            case GE -> a >= b;
            default -> throw new IllegalArgumentException("operator " + op.symbol + " on numbers");
        };
    }

    /** Converts a value for storage in data of a declared type (an int stored in a float becomes a double). */
    public static Object coerce(Object value, Type type) {
        if (type.kind() == Type.Kind.FLOAT && value instanceof Integer i) {
            return i.doubleValue();
        }
        return value;
    }

    /** @return the value a datum of this type holds before anything is assigned (Java's field defaults) */
    public static Object defaultValue(Type type) {
        return switch (type.kind()) {
            case INT -> 0;
            case FLOAT -> 0.0;
            case BOOL -> false;
            case STRING -> "";
            default -> null;
        };
    }
}
