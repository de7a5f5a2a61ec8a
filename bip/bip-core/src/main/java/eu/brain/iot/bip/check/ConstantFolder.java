package eu.brain.iot.bip.check;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.interp.Env;
import eu.brain.iot.bip.interp.Evaluator;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.Expr;

/**
 * Evaluates expressions made only of literals and package constants, with the interpreter's evaluator; anything
 * else (data, calls, ill-typed or failing expressions) folds to null.
 */
public final class ConstantFolder {

    private static final int MAX_DEPTH = 50;

    private ConstantFolder() {
    }

    public static Object fold(Expr e, PackageScope scope) {
        return fold(e, scope, 0);
    }

    private static Object fold(Expr e, PackageScope scope, int depth) {
        if (depth > MAX_DEPTH) {
            return null;
        }
        Evaluator evaluator = new Evaluator(new ExprTyper(scope, new Diagnostics()), LocalNames.constants(scope));
        try {
            return evaluator.eval(e, new Env() {
                @Override
                public Object get(Symbol symbol, String qualifiedName) {
                    if (symbol.kind() != Symbol.Kind.CONST) {
                        throw new NotConstant();
                    }
                    ConstDecl c = (ConstDecl) symbol.decl();
                    PackageScope owner = new PackageScope(scope.workspace(), scope.owner(c));
                    Object value = fold(c.value(), owner, depth + 1);
                    if (value == null) {
                        throw new NotConstant();
                    }
                    return value;
                }

                @Override
                public void set(Symbol symbol, String qualifiedName, Object value) {
                    throw new NotConstant();
                }

                @Override
                public Object call(ResolvedCall call, Object[] args) {
                    throw new NotConstant();
                }
            });
        } catch (RuntimeException notConstantOrIllTyped) {
            // data, calls, unknown names, ill-typed operands, division by zero: the checker reports what matters
            return null;
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
