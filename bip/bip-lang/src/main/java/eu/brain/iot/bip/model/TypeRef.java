package eu.brain.iot.bip.model;

/** A data type as written: a native type ({@code int, float, double, bool, string}) or an extern type name. */
public record TypeRef(Pos pos, String name) {
}
