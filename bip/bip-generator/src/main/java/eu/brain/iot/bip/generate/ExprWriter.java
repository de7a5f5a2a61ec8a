package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.Names;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Symbol;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Stmt;

/**
 * Writes expressions and statements as Java with the value semantics the interpreter has ({@code ==} on strings
 * compares contents, everything else is Java's own). Where names go is up to a {@link Mapper}.
 */
final class ExprWriter {

    /** Decides what names and calls become in the Java at hand. */
    interface Mapper {
        /** @return Java that reads the name */
        String read(Symbol symbol, Expr.Var var);

        /** @return the Java left-hand side for an assignment, or null to leave the statement out */
        String write(Symbol symbol, Expr.Var var);

        /** @return Java that calls the extern function */
        String call(ResolvedCall call, List<String> args);
    }

    private final ExprTyper typer;
    private final Names names;
    private final Mapper mapper;

    ExprWriter(ExprTyper typer, Names names, Mapper mapper) {
        this.typer = typer;
        this.names = names;
        this.mapper = mapper;
    }

    void statements(Code code, List<Stmt> stmts) {
        for (Stmt s : stmts) {
            statement(code, s);
        }
    }

    private void statement(Code code, Stmt s) {
        if (s instanceof Stmt.Assign a) {
            Symbol target = typer.symbol(a.target(), names);
            if (a.primed()) {
                code.line("// " + a.target().text() + "' = ...: clock rates have no meaning here");
                return;
            }
            String lhs = mapper.write(target, a.target());
            if (lhs != null) {
                code.line(lhs + " = " + expr(a.value()) + ";");
            }
        } else if (s instanceof Stmt.Call c) {
            code.line(call(c.call(), true) + ";");
        } else if (s instanceof Stmt.If i) {
            code.open("if (" + expr(i.condition()) + ")");
            statements(code, i.then());
            if (!i.otherwise().isEmpty()) {
                code.middle("} else {");
                statements(code, i.otherwise());
            }
            code.close();
        }
    }

    String expr(Expr e) {
        if (e instanceof Expr.IntLit i) {
            return i.value() > Integer.MAX_VALUE ? "((int) " + i.value() + "L)" : Long.toString(i.value());
        } else if (e instanceof Expr.FloatLit f) {
            return Double.toString(f.value());
        } else if (e instanceof Expr.BoolLit b) {
            return Boolean.toString(b.value());
        } else if (e instanceof Expr.StringLit s) {
            return JavaNames.literal(s.value());
        } else if (e instanceof Expr.Var v) {
            return mapper.read(typer.symbol(v, names), v);
        } else if (e instanceof Expr.Call c) {
            return call(c, false);
        } else if (e instanceof Expr.Unary u) {
            ResolvedCall op = typer.operator(u, names);
            return op != null ? mapper.call(op, List.of(expr(u.operand())))
                    : "(" + u.op().symbol + expr(u.operand()) + ")";
        }
        Expr.Binary b = (Expr.Binary) e;
        ResolvedCall op = typer.operator(b, names);
        if (op != null) {
            return mapper.call(op, List.of(expr(b.left()), expr(b.right())));
        }
        if (b.op() == Expr.BinaryOp.EQ || b.op() == Expr.BinaryOp.NE) {
            Type l = typer.type(b.left(), names);
            Type r = typer.type(b.right(), names);
            if (!(l.numeric() && r.numeric()) && l.kind() != Type.Kind.BOOL) {
                return "(" + (b.op() == Expr.BinaryOp.NE ? "!" : "") + "java.util.Objects.equals(" + expr(b.left())
                        + ", " + expr(b.right()) + "))";
            }
        }
        if (b.op() == Expr.BinaryOp.ADD && (typer.type(b.left(), names).kind() == Type.Kind.STRING
                || typer.type(b.right(), names).kind() == Type.Kind.STRING)) {
            return "(String.valueOf(" + expr(b.left()) + ") + " + expr(b.right()) + ")";
        }
        return "(" + expr(b.left()) + " " + b.op().symbol + " " + expr(b.right()) + ")";
    }

    private String call(Expr.Call c, boolean statement) {
        ResolvedCall r = typer.call(c, names, statement);
        List<String> args = new ArrayList<>();
        for (Expr a : c.args()) {
            args.add(expr(a));
        }
        return mapper.call(r, args);
    }
}
