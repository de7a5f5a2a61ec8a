package eu.brain.iot.bip.model;

/**
 * A typed parameter of a type declaration (port, atom, compound, connector type) or of an extern function. For a
 * connector type, {@code type} names a port type. {@code name} is null for unnamed extern function parameters.
 * {@code constant} is BIP2's {@code const} before the type ({@code extern function f(const int, T)},
 * {@code port type P(const int v)}): the value is read, never written, through this parameter.
 */
public record Param(Pos pos, TypeRef type, String name, boolean constant) {

    /** A parameter without {@code const}. */
    public Param(Pos pos, TypeRef type, String name) {
        this(pos, type, name, false);
    }
}
