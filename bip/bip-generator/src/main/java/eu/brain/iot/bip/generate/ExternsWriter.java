package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.Param;

/**
 * Writes the Java interface of the extern functions an atom type (and the connector code its behaviour runs)
 * calls; the behaviour bundle implements it by hand and registers it as an OSGi service.
 */
final class ExternsWriter {

    private ExternsWriter() {
    }

    /** @return the distinct signatures, reporting two that differ only in their result */
    static List<ResolvedCall> distinct(List<ResolvedCall> calls, AtomType atom, Diagnostics diagnostics) {
        Map<String, ResolvedCall> bySignature = new LinkedHashMap<>();
        for (ResolvedCall c : calls) {
            ResolvedCall previous = bySignature.putIfAbsent(c.signature(), c);
            if (previous != null && !previous.result().equals(c.result())) {
                diagnostics.error(atom.pos(), "cannot generate Java for atom type " + atom.name() + ": extern function "
                        + c.name() + c.params() + " is called with results " + previous.result() + " and " + c.result()
                        + " (Java cannot overload on the result)");
            }
        }
        return new ArrayList<>(bySignature.values());
    }

    static String write(String javaPackage, String name, AtomType atom, List<ResolvedCall> calls, PackageScope scope) {
        Code c = new Code();
        c.line("package " + javaPackage + ";").blank();
        c.line("/**");
        c.line(" * The extern functions atom type {@code " + atom.name() + "} calls (" + JavaNames.fileName(atom.pos()) + "),");
        c.line(" * generated: implement this interface by hand and register it as an OSGi service.");
        c.line(" * Calls come from the behaviour's lock, one at a time per behaviour.");
        c.line(" */");
        c.line("@javax.annotation.processing.Generated(\"eu.brain.iot.bip\")");
        c.open("public interface " + name);
        c.blank();
        c.line("/**");
        c.line(" * Called by the generated behaviour before the calls it makes for one instance (its initial transition,");
        c.line(" * guards, actions, connector code): the group (\"\" for the default one) and the component, e.g. Robot1;");
        c.line(" * the atom's own parameters are the same in every group. Does nothing unless overridden.");
        c.line(" *");
        c.line(" * @param group the group of the instance");
        c.line(" * @param component the component instance in the root compound");
        c.line(" */");
        c.open("default void bipInstance(String group, String component)");
        c.close();
        for (ResolvedCall call : calls) {
            List<String> params = new ArrayList<>();
            for (int i = 0; i < call.params().size(); i++) {
                String pname = call.decl() != null && call.decl().params().get(i).name() != null
                        ? JavaNames.id(call.decl().params().get(i).name()) : "arg" + i;
                params.add(JavaNames.javaType(call.params().get(i), scope) + " " + pname);
            }
            c.blank();
            c.line("/** {@code " + describe(call) + "} */");
            c.line(JavaNames.javaType(call.result(), scope) + " " + JavaNames.id(call.name()) + "("
                    + String.join(", ", params) + ");");
        }
        c.close();
        return c.toString();
    }

    private static String describe(ResolvedCall call) {
        if (call.decl() == null) {
            return call.name().startsWith("operator") ? "extern operator " + call.result() + " " + call.name()
                    + call.params() : "extern function " + call.name() + call.params() + " (from a qualified call)";
        }
        StringBuilder s = new StringBuilder("extern function ");
        if (call.decl().returnType() != null) {
            s.append(call.decl().returnType().name()).append(' ');
        }
        s.append(call.name()).append('(');
        List<String> ps = new ArrayList<>();
        for (Param p : call.decl().params()) {
            ps.add(p.name() == null ? p.type().name() : p.type().name() + " " + p.name());
        }
        return s.append(String.join(", ", ps)).append(')').toString();
    }

    static boolean isVoid(Type t) {
        return t.kind() == Type.Kind.VOID;
    }
}
