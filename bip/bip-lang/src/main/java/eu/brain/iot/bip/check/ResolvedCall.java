package eu.brain.iot.bip.check;

import java.util.List;

import eu.brain.iot.bip.model.ExternFunction;

/**
 * An extern function call after overload resolution: the signature the generated Java interface declares for it.
 * {@code decl} is null for a qualified call that matches no declaration (allowed by the BRAIN-IoT dialect, with a
 * warning), whose signature then comes from the call site, and for an extern operator ({@code operatorAdd}...).
 */
public record ResolvedCall(String name, List<Type> params, Type result, ExternFunction decl) {

    public ResolvedCall {
        params = List.copyOf(params);
    }

    /** @return the signature as a key: name and parameter types */
    public String signature() {
        return name + params;
    }
}
