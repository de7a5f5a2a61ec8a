package eu.brain.iot.bip.interp;

import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.Names;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Stmt;

/**
 * Evaluates expressions and runs statements of a checked model directly (no code generation), with the value
 * semantics of {@link Ops}. Name and call resolution is done once per expression node and cached. Not thread-safe.
 */
public final class Evaluator {

    private final ExprTyper typer;
    private final Names names;
    private final Map<Expr.Var, Symbol> symbols = new IdentityHashMap<>();
    private final Map<Expr.Call, ResolvedCall> calls = new IdentityHashMap<>();
    /** Per binary expression: the extern operator it calls, if its operands are of extern types. */
    private final Map<Expr.Binary, Optional<ResolvedCall>> operators = new IdentityHashMap<>();
    private final Map<Expr.Unary, Optional<ResolvedCall>> unaryOperators = new IdentityHashMap<>();

    /** @param typer a typer reporting into a scratch Diagnostics (the model is assumed checked) */
    public Evaluator(ExprTyper typer, Names names) {
        this.typer = typer;
        this.names = names;
    }

    public Symbol symbol(Expr.Var v) {
        Symbol s = symbols.get(v);
        if (s == null) {
            s = typer.symbol(v, names);
            if (s == null) {
                throw new IllegalStateException("unresolved name " + v.text() + " at " + v.pos());
            }
            symbols.put(v, s);
        }
        return s;
    }

    private ResolvedCall resolved(Expr.Call c, boolean statement) {
        ResolvedCall r = calls.get(c);
        if (r == null) {
            r = typer.call(c, names, statement);
            if (r == null) {
                throw new IllegalStateException("unresolved call " + c.text() + " at " + c.pos());
            }
            calls.put(c, r);
        }
        return r;
    }

    public void run(List<Stmt> stmts, Env env) {
        for (Stmt s : stmts) {
            if (s instanceof Stmt.Assign a) {
                Symbol target = symbol(a.target());
                Object value = eval(a.value(), env);
                if (!a.primed()) {
                    env.set(target, a.target().text(), Ops.coerce(value, target.type()));
                }
            } else if (s instanceof Stmt.Call c) {
                call(c.call(), env, true);
            } else if (s instanceof Stmt.If i) {
                if ((Boolean) eval(i.condition(), env)) {
                    run(i.then(), env);
                } else {
                    run(i.otherwise(), env);
                }
            }
        }
    }

    public boolean test(Expr guard, Env env) {
        return guard == null || (Boolean) eval(guard, env);
    }

    public Object eval(Expr e, Env env) {
        if (e instanceof Expr.IntLit i) {
            return (int) i.value();
        } else if (e instanceof Expr.FloatLit f) {
            return f.value();
        } else if (e instanceof Expr.BoolLit b) {
            return b.value();
        } else if (e instanceof Expr.StringLit s) {
            return s.value();
        } else if (e instanceof Expr.Var v) {
            Symbol s = symbol(v);
            return Ops.coerce(env.get(s, v.text()), s.type());
        } else if (e instanceof Expr.Call c) {
            return call(c, env, false);
        } else if (e instanceof Expr.Unary u) {
            ResolvedCall op = unaryOperators.computeIfAbsent(u, x -> Optional.ofNullable(typer.operator(x, names)))
                    .orElse(null);
            if (op != null) {
                return Ops.coerce(env.call(op, new Object[] {eval(u.operand(), env)}), op.result());
            }
            return Ops.unary(u.op(), eval(u.operand(), env));
        }
        Expr.Binary b = (Expr.Binary) e;
        ResolvedCall op = operators.computeIfAbsent(b, x -> Optional.ofNullable(typer.operator(x, names))).orElse(null);
        if (op != null) {
            return Ops.coerce(env.call(op, new Object[] {eval(b.left(), env), eval(b.right(), env)}), op.result());
        }
        Object l = eval(b.left(), env);
        if (b.op() == Expr.BinaryOp.AND) {
            return (Boolean) l && (Boolean) eval(b.right(), env);
        }
        if (b.op() == Expr.BinaryOp.OR) {
            return (Boolean) l || (Boolean) eval(b.right(), env);
        }
        return Ops.binary(b.op(), l, eval(b.right(), env));
    }

    private Object call(Expr.Call c, Env env, boolean statement) {
        ResolvedCall r = resolved(c, statement);
        Object[] args = new Object[c.args().size()];
        for (int i = 0; i < args.length; i++) {
            Object v = eval(c.args().get(i), env);
            Type p = i < r.params().size() ? r.params().get(i) : Type.ERROR;
            args[i] = Ops.coerce(v, p);
        }
        Object result = env.call(r, args);
        return result == null ? null : Ops.coerce(result, r.result());
    }
}
