package eu.brain.iot.bip.check;

/** The names an expression may use where it is written (an atom, a connector, a compound). */
public interface Names {

    /** @return the symbol for a plain name, or null */
    Symbol lookup(String name);

    /** @return the symbol for {@code qualifier.name}, or null */
    Symbol lookup(String qualifier, String name);

    /** @return what a qualified name should look like here, for messages */
    String qualifiedHint();
}
