package eu.brain.iot.bip.interp;

import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;

/** Where the evaluator reads and writes names and sends extern calls. */
public interface Env {

    Object get(Symbol symbol, String qualifiedName);

    void set(Symbol symbol, String qualifiedName, Object value);

    /** Calls an extern function; arguments are already converted to its parameter types. */
    Object call(ResolvedCall call, Object[] args);
}
