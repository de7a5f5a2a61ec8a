package eu.brain.iot.bip.check;

/** What a name in an expression stands for, and its type. */
public record Symbol(Kind kind, String name, Type type, Object decl) {

    public enum Kind {
        /** atom or connector data: readable and assignable */
        DATA,
        /** atom or compound parameter: read-only */
        PARAM,
        /** package constant: read-only */
        CONST,
        /** timed BIP clock: read, reset by assignment */
        CLOCK,
        /** {@code port.var} in a connector */
        PORT_DATA,
        /** {@code component.data} in a compound priority guard: read-only */
        COMPONENT_DATA
    }

    public boolean assignable() {
        return kind == Kind.DATA || kind == Kind.CLOCK || kind == Kind.PORT_DATA && !constant();
    }

    /** @return whether this is port data its port type declares {@code const} (read-only in connectors) */
    public boolean constant() {
        return kind == Kind.PORT_DATA && decl instanceof eu.brain.iot.bip.model.Param p && p.constant();
    }
}
