package eu.brain.iot.bip.generate;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.Expr;

/** What {@link SimulationWriter} and {@link SimulationAtomWriter} share: extern calls in simulation, static facts. */
final class SimulationCode {

    private SimulationCode() {
    }

    /** @return the port parameters whose data the clause's up or down assigns */
    static Set<String> written(ConnectorType.Interaction clause) {
        Set<String> out = new LinkedHashSet<>();
        if (clause.up() != null) {
            assigned(clause.up().stmts(), out);
        }
        if (clause.down() != null) {
            assigned(clause.down().stmts(), out);
        }
        return out;
    }

    private static void assigned(List<eu.brain.iot.bip.model.Stmt> stmts, Set<String> out) {
        for (eu.brain.iot.bip.model.Stmt s : stmts) {
            if (s instanceof eu.brain.iot.bip.model.Stmt.Assign a && a.target().qualifier() != null) {
                out.add(a.target().qualifier());
            } else if (s instanceof eu.brain.iot.bip.model.Stmt.If i) {
                assigned(i.then(), out);
                assigned(i.otherwise(), out);
            }
        }
    }

    /**
     * @return whether firing the port cannot change the atom: every transition it labels goes back to the places
     *         it came from, has no action, and a guard that calls nothing (a call could draw a random number)
     */
    static boolean pureSelfLoops(AtomType atom, String port) {
        List<AtomType.Transition> ts = atom.transitions().stream().filter(t -> port.equals(t.port())).toList();
        return !ts.isEmpty() && ts.stream().allMatch(t -> Set.copyOf(t.from()).equals(Set.copyOf(t.to()))
                && t.from().size() == t.to().size() && (t.action() == null || t.action().stmts().isEmpty())
                && (t.guard() == null || !hasCall(t.guard())));
    }

    private static boolean hasCall(Expr e) {
        if (e instanceof Expr.Call) {
            return true;
        } else if (e instanceof Expr.Unary u) {
            return hasCall(u.operand());
        } else if (e instanceof Expr.Binary b) {
            return hasCall(b.left()) || hasCall(b.right());
        }
        return false;
    }

    /** The Java of an extern call in simulation: a built-in draws from the trace's random source. */
    static String callExpr(ResolvedCall call, List<String> args, PackageScope scope, String random, String simulation,
            SimulationBuiltins builtins) {
        List<String> types = call.params().stream().map(Type::toString).toList();
        String result = call.result().toString();
        if (builtins.isBuiltin(call.name(), types, result)) {
            return random + "." + call.name() + "(" + String.join(", ", args) + ")";
        }
        String generic = "eu.brain.iot.bip.smc.runtime.Builtins.simulate(" + simulation + ", "
                + JavaNames.literal(call.name()) + ", java.util.List.of("
                + String.join(", ", types.stream().map(JavaNames::literal).toList()) + "), "
                + JavaNames.literal(result) + ", new Object[] {" + String.join(", ", args) + "}, " + random + ")";
        return switch (call.result().kind()) {
            case VOID -> generic;
            case INT -> "((Integer) " + generic + ")";
            case FLOAT -> "((Number) " + generic + ").doubleValue()";
            case BOOL -> "((Boolean) " + generic + ")";
            case STRING -> "((String) " + generic + ")";
            default -> "((" + JavaNames.javaType(call.result(), scope) + ") " + generic + ")";
        };
    }

    static String callBody(ResolvedCall call, List<String> args, PackageScope scope, String random, String simulation,
            SimulationBuiltins builtins) {
        String e = callExpr(call, args, scope, random, simulation, builtins);
        return call.result().kind() == Type.Kind.VOID ? e + ";" : "return " + e + ";";
    }

}
