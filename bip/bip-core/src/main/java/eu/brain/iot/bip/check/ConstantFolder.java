package eu.brain.iot.bip.check;

import eu.brain.iot.bip.interp.Ops;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.Expr;

/** Evaluates expressions made only of literals and package constants; anything else folds to null. */
public final class ConstantFolder {

    private ConstantFolder() {
    }

    public static Object fold(Expr e, PackageScope scope) {
        return fold(e, scope, 0);
    }

    private static Object fold(Expr e, PackageScope scope, int depth) {
        if (depth > 50) {
            return null;
        }
        try {
            if (e instanceof Expr.IntLit i) {
                return (int) i.value();
            } else if (e instanceof Expr.FloatLit f) {
                return f.value();
            } else if (e instanceof Expr.BoolLit b) {
                return b.value();
            } else if (e instanceof Expr.StringLit s) {
                return s.value();
            } else if (e instanceof Expr.Var v) {
                String name = v.qualifier() == null ? v.name() : v.text();
                ConstDecl c = scope.constant(name).orElse(null);
                if (c == null) {
                    return null;
                }
                Object value = fold(c.value(), scope, depth + 1);
                Type t = scope.resolveType(c.type().name());
                return value == null || t == null ? value : Ops.coerce(value, t);
            } else if (e instanceof Expr.Unary u) {
                Object v = fold(u.operand(), scope, depth + 1);
                return v == null ? null : Ops.unary(u.op(), v);
            } else if (e instanceof Expr.Binary b) {
                Object l = fold(b.left(), scope, depth + 1);
                if (b.op() == Expr.BinaryOp.AND && Boolean.FALSE.equals(l)) {
                    return false;
                }
                if (b.op() == Expr.BinaryOp.OR && Boolean.TRUE.equals(l)) {
                    return true;
                }
                Object r = fold(b.right(), scope, depth + 1);
                if (l == null || r == null) {
                    return null;
                }
                if (b.op().logical()) {
                    return r;
                }
                return Ops.binary(b.op(), l, r);
            }
        } catch (RuntimeException ex) {
            // ill-typed or dividing by zero: the checker reports types; folding just gives up
            return null;
        }
        return null;
    }
}
