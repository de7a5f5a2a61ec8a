package eu.brain.iot.bip.check;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.Expr;

/**
 * Evaluates expressions made only of literals and package constants with the language's value semantics
 * ({@link Values}); anything else (data, calls, ill-typed or failing expressions) folds to null. It walks the
 * expression itself rather than using the interpreter, so that {@code check} never depends on {@code interp}.
 */
public final class ConstantFolder {

    private static final int MAX_DEPTH = 50;

    private ConstantFolder() {
    }

    public static Object fold(Expr e, PackageScope scope) {
        try {
            return new Fold(scope, 0).eval(e);
        } catch (RuntimeException notConstantOrIllTyped) {
            // data, calls, unknown names, ill-typed operands, division by zero: the checker reports what matters
            return null;
        }
    }

    private record Fold(PackageScope scope, int depth) {

        Object eval(Expr e) {
            if (e instanceof Expr.IntLit i) {
                return (int) i.value();
            } else if (e instanceof Expr.FloatLit f) {
                return f.value();
            } else if (e instanceof Expr.BoolLit b) {
                return b.value();
            } else if (e instanceof Expr.StringLit s) {
                return s.value();
            } else if (e instanceof Expr.Var v) {
                return constant(v);
            } else if (e instanceof Expr.Unary u) {
                return Values.unary(u.op(), eval(u.operand()));
            } else if (e instanceof Expr.Binary b) {
                Object l = eval(b.left());
                if (b.op() == Expr.BinaryOp.AND) {
                    return (Boolean) l && (Boolean) eval(b.right());
                }
                if (b.op() == Expr.BinaryOp.OR) {
                    return (Boolean) l || (Boolean) eval(b.right());
                }
                return Values.binary(b.op(), l, eval(b.right()));
            }
            throw new NotConstant();
        }

        private Object constant(Expr.Var v) {
            if (depth > MAX_DEPTH) {
                throw new NotConstant();
            }
            Symbol s = new ExprTyper(scope, new Diagnostics()).symbol(v, LocalNames.constants(scope));
            if (s == null || s.kind() != Symbol.Kind.CONST) {
                throw new NotConstant();
            }
            ConstDecl c = (ConstDecl) s.decl();
            Object value = new Fold(new PackageScope(scope.workspace(), scope.owner(c)), depth + 1).eval(c.value());
            return Values.coerce(value, s.type());
        }
    }

    /** Control flow: the expression depends on something that is not a constant. */
    private static final class NotConstant extends RuntimeException {
        private static final long serialVersionUID = 1L;

        NotConstant() {
            super(null, null, false, false);
        }
    }
}
