package eu.brain.iot.bip.smc.query;

import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.interp.Ops;
import eu.brain.iot.bip.model.Expr.BinaryOp;
import eu.brain.iot.bip.model.Expr.UnaryOp;

/** A resolved expression of a query's atomic propositions, over component data, places and parameters. */
public sealed interface Term {

    Type type();

    /** What a term reads from a state. */
    interface State {
        Object data(int atom, String name);

        boolean at(int atom, String place);

        double param(int index);
    }

    /** An int, float or bool literal, or a model constant's value. */
    record Lit(Object value, Type type) implements Term {
    }

    /** Datum (or parameter) {@code name} of atom instance {@code atom} (its index in the flattened system). */
    record Data(int atom, String path, String name, Type type) implements Term {
    }

    /** {@code path at place}. */
    record At(int atom, String path, String place) implements Term {
        @Override
        public Type type() {
            return Type.BOOL;
        }
    }

    /** A swept parameter: {@code index} into the parameter values of the query. */
    record Param(int index, String name, Type type) implements Term {
    }

    record Unary(UnaryOp op, Term operand, Type type) implements Term {
    }

    record Binary(BinaryOp op, Term left, Term right, Type type) implements Term {
    }

    /** Evaluates the term with the interpreter's value semantics (those of the generated Java). */
    static Object eval(Term t, State s) {
        if (t instanceof Lit l) {
            return l.value();
        } else if (t instanceof Data d) {
            return s.data(d.atom(), d.name());
        } else if (t instanceof At a) {
            return s.at(a.atom(), a.place());
        } else if (t instanceof Param p) {
            return p.type().kind() == Type.Kind.INT ? (Object) (int) s.param(p.index()) : (Object) s.param(p.index());
        } else if (t instanceof Unary u) {
            return Ops.unary(u.op(), eval(u.operand(), s));
        }
        Binary b = (Binary) t;
        if (b.op() == BinaryOp.AND) {
            return (Boolean) eval(b.left(), s) && (Boolean) eval(b.right(), s);
        }
        if (b.op() == BinaryOp.OR) {
            return (Boolean) eval(b.left(), s) || (Boolean) eval(b.right(), s);
        }
        return Ops.binary(b.op(), eval(b.left(), s), eval(b.right(), s));
    }
}
