package eu.brain.iot.bip.check;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.ExternFunction;
import eu.brain.iot.bip.model.ExternOperator;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Expr.BinaryOp;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.Stmt;

/**
 * Types expressions and statements, resolving names and extern function overloads. The checker uses it to report
 * problems; the generator and the interpreter use it (reporting into a scratch {@link Diagnostics}) to learn the
 * type of each expression and the signature of each call.
 */
public final class ExprTyper {

    private final PackageScope scope;
    private final Diagnostics diagnostics;

    public ExprTyper(PackageScope scope, Diagnostics diagnostics) {
        this.scope = scope;
        this.diagnostics = diagnostics;
    }

    public PackageScope scope() {
        return scope;
    }

    // ---------------------------------------------------------------- statements

    public void statements(List<Stmt> stmts, Names names) {
        for (Stmt s : stmts) {
            statement(s, names);
        }
    }

    public void statement(Stmt s, Names names) {
        if (s instanceof Stmt.Assign a) {
            Symbol target = symbol(a.target(), names);
            Type value = type(a.value(), names);
            if (target == null) {
                return;
            }
            if (target.constant()) {
                diagnostics.error(a.pos(), "cannot assign to " + a.target().text() + ": its port type declares "
                        + target.name().substring(target.name().indexOf('.') + 1) + " 'const' (read-only)");
            } else if (!target.assignable()) {
                diagnostics.error(a.pos(), "cannot assign to " + a.target().text() + ": it is a "
                        + target.kind().name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ')
                        + ", which is read-only");
            } else if (a.primed() && target.kind() != Symbol.Kind.CLOCK) {
                diagnostics.error(a.pos(), "only a clock's rate can be set with " + a.target().text()
                        + "'; " + a.target().text() + " is not a clock");
            } else if (!scope.assignable(target.type(), value)) {
                diagnostics.error(a.value().pos(), "cannot assign a value of type " + value + " to "
                        + a.target().text() + " of type " + target.type());
            }
        } else if (s instanceof Stmt.Call c) {
            call(c.call(), names, true);
        } else if (s instanceof Stmt.If i) {
            expectBool(i.condition(), names, "the condition of 'if'");
            statements(i.then(), names);
            statements(i.otherwise(), names);
        }
    }

    public void expectBool(Expr e, Names names, String what) {
        Type t = type(e, names);
        if (!t.isError() && t.kind() != Type.Kind.BOOL) {
            diagnostics.error(e.pos(), what + " must be a bool, but '" + eu.brain.iot.bip.print.Printer.print(e)
                    + "' is of type " + t);
        }
    }

    // ---------------------------------------------------------------- expressions

    public Symbol symbol(Expr.Var v, Names names) {
        Symbol s = v.qualifier() == null ? names.lookup(v.name()) : names.lookup(v.qualifier(), v.name());
        if (s == null) {
            if (v.qualifier() == null) {
                diagnostics.error(v.pos(), "unknown name '" + v.name()
                        + "': not a data, parameter or constant visible here");
            } else {
                diagnostics.error(v.pos(), "unknown name '" + v.text() + "': expected " + names.qualifiedHint());
            }
        }
        return s;
    }

    public Type type(Expr e, Names names) {
        if (e instanceof Expr.IntLit i) {
            if (i.value() > Integer.MAX_VALUE + 1L) {
                diagnostics.error(i.pos(), "integer " + i.value() + " does not fit in an int");
            }
            return Type.INT;
        } else if (e instanceof Expr.FloatLit) {
            return Type.FLOAT;
        } else if (e instanceof Expr.BoolLit) {
            return Type.BOOL;
        } else if (e instanceof Expr.StringLit) {
            return Type.STRING;
        } else if (e instanceof Expr.Var v) {
            Symbol s = symbol(v, names);
            return s == null ? Type.ERROR : s.type();
        } else if (e instanceof Expr.Call c) {
            ResolvedCall r = call(c, names, false);
            return r == null ? Type.ERROR : r.result();
        } else if (e instanceof Expr.Unary u) {
            return unary(u, names);
        }
        return binary((Expr.Binary) e, names);
    }

    private Type unary(Expr.Unary u, Names names) {
        Type t = type(u.operand(), names);
        if (t.isError()) {
            return t;
        }
        if (t.kind() == Type.Kind.EXTERN) {
            ExternOperator op = externOperator(u.op().symbol, t);
            if (op == null) {
                return mismatch(u, "no operator '" + u.op().symbol + "' for " + t
                        + " (declare one with 'extern operator')", t);
            }
            Type result = scope.resolveType(op.returnType().name());
            return result == null ? Type.ERROR : result;
        }
        return switch (u.op()) {
            case NOT -> t.kind() == Type.Kind.BOOL ? Type.BOOL : mismatch(u, "'!' needs a bool", t);
            case NEG, PLUS -> t.numeric() ? t : mismatch(u, "'" + u.op().symbol + "' needs a number", t);
            case BIT_NOT -> t.kind() == Type.Kind.INT ? Type.INT : mismatch(u, "'~' needs an int", t);
        };
    }

    private Type mismatch(Expr e, String what, Type got) {
        diagnostics.error(e.pos(), what + ", but got " + got + " in '" + eu.brain.iot.bip.print.Printer.print(e) + "'");
        return Type.ERROR;
    }

    private Type binary(Expr.Binary b, Names names) {
        Type l = type(b.left(), names);
        Type r = type(b.right(), names);
        if (l.isError() || r.isError()) {
            return b.op().comparison() || b.op().logical() ? Type.BOOL : Type.ERROR;
        }
        if (l.kind() == Type.Kind.EXTERN || r.kind() == Type.Kind.EXTERN) {
            ExternOperator op = externOperator(b.op(), l, r);
            if (op != null) {
                Type result = scope.resolveType(op.returnType().name());
                return result == null ? Type.ERROR : result;
            }
            if ((b.op() == BinaryOp.EQ || b.op() == BinaryOp.NE) && l.equals(r)) {
                return Type.BOOL;
            }
            return mismatch(b, "no operator '" + b.op().symbol + "' for " + l + " and " + r
                    + " (declare one with 'extern operator')", l.kind() == Type.Kind.EXTERN ? l : r);
        }
        BinaryOp op = b.op();
        if (op.logical()) {
            if (l.kind() != Type.Kind.BOOL || r.kind() != Type.Kind.BOOL) {
                return mismatch(b, "'" + op.symbol + "' needs two bools", l.kind() != Type.Kind.BOOL ? l : r);
            }
            return Type.BOOL;
        }
        if (op == BinaryOp.EQ || op == BinaryOp.NE) {
            if ((l.numeric() && r.numeric()) || l.equals(r)) {
                return Type.BOOL;
            }
            return mismatch(b, "cannot compare " + l + " with " + r, r);
        }
        if (op.comparison()) {
            if (l.numeric() && r.numeric()) {
                return Type.BOOL;
            }
            return mismatch(b, "'" + op.symbol + "' needs two numbers", l.numeric() ? r : l);
        }
        if (op == BinaryOp.ADD && (l.kind() == Type.Kind.STRING || r.kind() == Type.Kind.STRING)) {
            if (l.kind() == Type.Kind.VOID || r.kind() == Type.Kind.VOID) {
                return mismatch(b, "'+' cannot join a call without result", Type.VOID);
            }
            return Type.STRING;
        }
        if (op.bitwise()) {
            if (l.kind() == Type.Kind.INT && r.kind() == Type.Kind.INT) {
                return Type.INT;
            }
            return mismatch(b, "'" + op.symbol + "' needs two ints", l.kind() == Type.Kind.INT ? r : l);
        }
        if (l.numeric() && r.numeric()) {
            boolean integral = l.kind() == Type.Kind.INT && r.kind() == Type.Kind.INT;
            if (integral && (op == BinaryOp.DIV || op == BinaryOp.MOD)
                    && Integer.valueOf(0).equals(ConstantFolder.fold(b.right(), scope))) {
                diagnostics.error(b.right().pos(), "integer " + (op == BinaryOp.DIV ? "division" : "remainder")
                        + " by zero: the divisor is always 0, so this always fails when it runs");
            }
            return integral ? Type.INT : Type.FLOAT;
        }
        return mismatch(b, "'" + op.symbol + "' needs two numbers", l.numeric() ? r : l);
    }

    private ExternOperator externOperator(BinaryOp symbol, Type l, Type r) {
        for (ExternOperator op : scope.operators(symbol.symbol)) {
            if (op.params().size() == 2 && scope.assignable(scope.resolveType(op.params().get(0).name()), l)
                    && scope.assignable(scope.resolveType(op.params().get(1).name()), r)) {
                return op;
            }
        }
        return null;
    }

    private ExternOperator externOperator(String symbol, Type operand) {
        for (ExternOperator op : scope.operators(symbol)) {
            if (op.params().size() == 1 && scope.assignable(scope.resolveType(op.params().get(0).name()), operand)) {
                return op;
            }
        }
        return null;
    }

    /**
     * @return the extern operator a unary expression on an extern type calls, as a call of {@code operatorNeg},
     *         {@code operatorNot}, ... (see {@link #operator(Expr.Binary, Names)}), or null
     */
    public ResolvedCall operator(Expr.Unary u, Names names) {
        Type t = type(u.operand(), names);
        ExternOperator op = t.kind() == Type.Kind.EXTERN ? externOperator(u.op().symbol, t) : null;
        if (op == null) {
            return null;
        }
        Type result = scope.resolveType(op.returnType().name());
        return new ResolvedCall(operatorName(u.op().name()), List.of(scope.resolveType(op.params().get(0).name())),
                result == null ? Type.ERROR : result, null);
    }

    private static String operatorName(String enumName) {
        String name = enumName.toLowerCase(java.util.Locale.ROOT).replace("_", "");
        return "operator" + Character.toUpperCase(name.charAt(0)) + name.substring(1);
    }

    /**
     * @return the extern operator a binary expression on extern types calls, as a call of the extern function
     *         {@code operatorAdd}, {@code operatorEq}, ... (the name the generated interface and the interpreter's
     *         {@code ExternFunctions} use), or null when the operator is the language's own
     */
    public ResolvedCall operator(Expr.Binary b, Names names) {
        Type l = type(b.left(), names);
        Type r = type(b.right(), names);
        if (l.kind() != Type.Kind.EXTERN && r.kind() != Type.Kind.EXTERN) {
            return null;
        }
        ExternOperator op = externOperator(b.op(), l, r);
        if (op == null) {
            return null;
        }
        Type result = scope.resolveType(op.returnType().name());
        return new ResolvedCall(operatorName(b.op().name()),
                List.of(scope.resolveType(op.params().get(0).name()), scope.resolveType(op.params().get(1).name())),
                result == null ? Type.ERROR : result, null);
    }

    /** Resolves a call; {@code statement} tells whether its result is unused (then a void function is fine). */
    public ResolvedCall call(Expr.Call c, Names names, boolean statement) {
        List<Type> args = new ArrayList<>();
        for (Expr a : c.args()) {
            args.add(type(a, names));
        }
        if (c.qualifier() != null && !scope.knownQualifier(c.qualifier())) {
            diagnostics.warning(c.pos(), "qualifier '" + c.qualifier() + "' of " + c.text()
                    + " is neither a @java(import=...) name nor a package; the call goes to extern function "
                    + c.name());
        }
        List<ExternFunction> candidates = scope.functions(c.name());
        if (candidates.isEmpty()) {
            diagnostics.error(c.pos(), "unknown function '" + c.text() + "': declare it with 'extern function'");
            return null;
        }
        List<ExternFunction> matching = new ArrayList<>();
        for (ExternFunction f : candidates) {
            if (f.params().size() == args.size() && accepts(f, args)) {
                matching.add(f);
            }
        }
        ExternFunction chosen = mostPrecise(matching);
        if (chosen == null && matching.size() > 1) {
            diagnostics.error(c.pos(), "ambiguous call " + c.text() + args + ": it matches " + matching.size()
                    + " declarations equally well");
            return null;
        }
        ResolvedCall resolved;
        if (chosen == null) {
            String declared = candidates.stream().map(ExprTyper::signature).reduce((a, b) -> a + ", " + b).orElse("");
            if (c.qualifier() == null) {
                diagnostics.error(c.pos(), "no declaration of " + c.name() + " takes " + describe(args)
                        + "; declared: " + declared);
                return null;
            }
            // BRAIN-IoT dialect: a qualified call names a Java class that decides; use the call site's signature.
            diagnostics.warning(c.pos(), "no declaration of " + c.name() + " takes " + describe(args) + " (declared: "
                    + declared + "); the generated interface gets " + c.name() + describe(args));
            Type result = candidates.stream().map(f -> resultType(f)).distinct().count() == 1
                    ? resultType(candidates.get(0)) : Type.VOID;
            resolved = new ResolvedCall(c.name(), widen(args), result, null);
        } else {
            List<Type> params = new ArrayList<>();
            for (Param p : chosen.params()) {
                Type t = scope.resolveType(p.type().name());
                params.add(t == null ? Type.ERROR : t);
            }
            resolved = new ResolvedCall(chosen.name(), params, resultType(chosen), chosen);
        }
        if (!statement && resolved.result().kind() == Type.Kind.VOID) {
            diagnostics.error(c.pos(), "function " + c.text() + " returns no value, but its value is used here");
            return new ResolvedCall(resolved.name(), resolved.params(), Type.ERROR, resolved.decl());
        }
        return resolved;
    }

    private static List<Type> widen(List<Type> args) {
        return args.stream().map(t -> t.isError() ? Type.INT : t).toList();
    }

    private Type resultType(ExternFunction f) {
        if (f.returnType() == null) {
            return Type.VOID;
        }
        Type t = scope.resolveType(f.returnType().name());
        return t == null ? Type.ERROR : t;
    }

    private boolean accepts(ExternFunction f, List<Type> args) {
        for (int i = 0; i < args.size(); i++) {
            Type p = scope.resolveType(f.params().get(i).type().name());
            if (p != null && !scope.assignable(p, args.get(i))) {
                return false;
            }
        }
        return true;
    }

    /** @return the one matching declaration at least as precise as all others, or null */
    private ExternFunction mostPrecise(List<ExternFunction> matching) {
        for (ExternFunction f : matching) {
            boolean best = true;
            for (ExternFunction g : matching) {
                if (g != f && !atLeastAsPrecise(f, g)) {
                    best = false;
                    break;
                }
            }
            if (best) {
                return f;
            }
        }
        return null;
    }

    private boolean atLeastAsPrecise(ExternFunction f, ExternFunction g) {
        for (int i = 0; i < f.params().size(); i++) {
            Type pf = scope.resolveType(f.params().get(i).type().name());
            Type pg = scope.resolveType(g.params().get(i).type().name());
            if (pf == null || pg == null || !scope.assignable(pg, pf)) {
                return false;
            }
        }
        return true;
    }

    static String signature(ExternFunction f) {
        return (f.returnType() == null ? "" : f.returnType().name() + " ") + f.name() + "("
                + String.join(", ", f.params().stream().map(p -> p.type().name()).toList()) + ")";
    }

    private static String describe(List<Type> args) {
        return "(" + String.join(", ", args.stream().map(Type::toString).toList()) + ")";
    }
}
