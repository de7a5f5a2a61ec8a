package eu.brain.iot.bip.model;

/**
 * A typed parameter of a type declaration (port, atom, compound, connector type) or of an extern function. For a
 * connector type, {@code type} names a port type. {@code name} is null for unnamed extern function parameters.
 */
public record Param(Pos pos, TypeRef type, String name) {
}
