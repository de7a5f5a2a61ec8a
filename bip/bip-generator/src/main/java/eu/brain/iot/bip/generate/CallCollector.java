package eu.brain.iot.bip.generate;

import java.util.List;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.Names;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Stmt;

/** Walks expressions and statements, collecting resolved extern calls (and visiting names, for subclasses). */
class CallCollector {

    private final ExprTyper typer;
    private final Names names;
    private final List<ResolvedCall> calls;

    CallCollector(ExprTyper typer, Names names, List<ResolvedCall> calls) {
        this.typer = typer;
        this.names = names;
        this.calls = calls;
    }

    void atom(AtomType atom) {
        atom.data().forEach(d -> expr(d.init()));
        if (atom.initial() != null && atom.initial().action() != null) {
            stmts(atom.initial().action().stmts());
        }
        for (AtomType.Transition t : atom.transitions()) {
            expr(t.guard());
            if (t.action() != null) {
                stmts(t.action().stmts());
            }
        }
        atom.priorities().forEach(p -> expr(p.guard()));
        atom.invariants().forEach(i -> expr(i.condition()));
    }

    void var(Expr.Var v) {
        // names are of no interest here
    }

    void stmts(List<Stmt> stmts) {
        for (Stmt s : stmts) {
            if (s instanceof Stmt.Assign a) {
                var(a.target());
                expr(a.value());
            } else if (s instanceof Stmt.Call c) {
                call(c.call(), true);
            } else if (s instanceof Stmt.If i) {
                expr(i.condition());
                stmts(i.then());
                stmts(i.otherwise());
            }
        }
    }

    void expr(Expr e) {
        if (e == null) {
            return;
        }
        if (e instanceof Expr.Var v) {
            var(v);
        } else if (e instanceof Expr.Call c) {
            call(c, false);
        } else if (e instanceof Expr.Unary u) {
            expr(u.operand());
            ResolvedCall op = typer.operator(u, names);
            if (op != null) {
                calls.add(op);
            }
        } else if (e instanceof Expr.Binary b) {
            expr(b.left());
            expr(b.right());
            ResolvedCall op = typer.operator(b, names);
            if (op != null) {
                calls.add(op);
            }
        }
    }

    private void call(Expr.Call c, boolean statement) {
        c.args().forEach(this::expr);
        ResolvedCall r = typer.call(c, names, statement);
        if (r != null) {
            calls.add(r);
        }
    }
}
