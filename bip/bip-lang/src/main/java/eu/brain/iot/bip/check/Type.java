package eu.brain.iot.bip.check;

/**
 * A resolved data type. {@code float} and {@code double} are one type (BIP2 maps float to double); {@code int} is a
 * sub-type of it. {@link Kind#ERROR} stands for a type that could not be worked out (already reported), and is
 * compatible with everything so that one mistake is reported once.
 */
public record Type(Kind kind, String externName) {

    public enum Kind {
        INT, FLOAT, BOOL, STRING, EXTERN, VOID, ERROR
    }

    public static final Type INT = new Type(Kind.INT, null);
    public static final Type FLOAT = new Type(Kind.FLOAT, null);
    public static final Type BOOL = new Type(Kind.BOOL, null);
    public static final Type STRING = new Type(Kind.STRING, null);
    public static final Type VOID = new Type(Kind.VOID, null);
    public static final Type ERROR = new Type(Kind.ERROR, null);

    public static Type extern(String name) {
        return new Type(Kind.EXTERN, name);
    }

    /** @return the native type of a written name, or null if it is not native */
    public static Type nativeType(String name) {
        return switch (name) {
            case "int" -> INT;
            case "float", "double" -> FLOAT;
            case "bool" -> BOOL;
            case "string" -> STRING;
            default -> null;
        };
    }

    public boolean numeric() {
        return kind == Kind.INT || kind == Kind.FLOAT || kind == Kind.ERROR;
    }

    public boolean isError() {
        return kind == Kind.ERROR;
    }

    @Override
    public String toString() {
        return switch (kind) {
            case EXTERN -> externName;
            case VOID -> "no value";
            case ERROR -> "<error>";
            default -> kind.name().toLowerCase(java.util.Locale.ROOT);
        };
    }
}
