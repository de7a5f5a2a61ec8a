package eu.brain.iot.bip.smc.query;

import java.util.function.IntPredicate;

/**
 * Decides a bounded LTL formula on a trace as it is produced, by formula progression: {@link #observe} rewrites the
 * formula into what must hold from the next state on, given the current state; the trace stops as soon as the
 * result is {@code true} or {@code false}. A proposition is read at most once per state. Owned by one thread.
 */
public final class Monitor {

    /** A progressed formula: immutable nodes; bounds are concrete. */
    private abstract static class Node {
    }

    private static final class Const extends Node {
        final boolean value;

        Const(boolean value) {
            this.value = value;
        }
    }

    private static final Const TRUE = new Const(true);
    private static final Const FALSE = new Const(false);

    private static final class Ap extends Node {
        final int index;

        Ap(int index) {
            this.index = index;
        }
    }

    private static final class Not extends Node {
        final Node operand;

        Not(Node operand) {
            this.operand = operand;
        }
    }

    private static final class And extends Node {
        final Node left;
        final Node right;

        And(Node left, Node right) {
            this.left = left;
            this.right = right;
        }
    }

    private static final class Or extends Node {
        final Node left;
        final Node right;

        Or(Node left, Node right) {
            this.left = left;
            this.right = right;
        }
    }

    private static final class Next extends Node {
        final Node operand;

        Next(Node operand) {
            this.operand = operand;
        }
    }

    /** {@code left U<=bound right}; {@code chain[k]} is the same until with bound k (built once, shared). */
    private static final class Until extends Node {
        final Node left;
        final Node right;
        final int bound;
        final Until[] chain;

        Until(Node left, Node right, int bound, Until[] chain) {
            this.left = left;
            this.right = right;
            this.bound = bound;
            this.chain = chain;
        }
    }

    private final Node root;
    private final int propositionCount;
    private Node current;
    private IntPredicate state;
    private final int[] stamp;
    private final boolean[] value;
    private int epoch;

    /** @param params the values of the query's swept parameters (step bounds may use them) */
    public Monitor(Formula formula, int propositionCount, double[] params) {
        this.root = build(formula, params);
        this.propositionCount = propositionCount;
        this.stamp = new int[propositionCount];
        this.value = new boolean[propositionCount];
        this.current = root;
    }

    private static Node build(Formula f, double[] params) {
        if (f instanceof Formula.Const c) {
            return c.value() ? TRUE : FALSE;
        } else if (f instanceof Formula.Ap a) {
            return new Ap(a.index());
        } else if (f instanceof Formula.Not n) {
            return new Not(build(n.operand(), params));
        } else if (f instanceof Formula.And a) {
            return new And(build(a.left(), params), build(a.right(), params));
        } else if (f instanceof Formula.Or o) {
            return new Or(build(o.left(), params), build(o.right(), params));
        } else if (f instanceof Formula.Next n) {
            return new Next(build(n.operand(), params));
        }
        Formula.Until u = (Formula.Until) f;
        int bound = Math.max(0, u.bound().resolve(params));
        Until[] chain = new Until[bound + 1];
        Node left = build(u.left(), params);
        Node right = build(u.right(), params);
        for (int k = 0; k <= bound; k++) {
            chain[k] = new Until(left, right, k, chain);
        }
        return chain[bound];
    }

    /** Starts a new trace. */
    public void reset() {
        current = root;
    }

    /**
     * Feeds the next state of the trace (state 0 first).
     *
     * @param propositions the state's atomic propositions by index
     * @return 1 when the formula holds, 0 when it does not, -1 when the next state is needed
     */
    public int observe(IntPredicate propositions) {
        state = propositions;
        epoch++;
        if (epoch == Integer.MAX_VALUE) {
            java.util.Arrays.fill(stamp, 0);
            epoch = 1;
        }
        current = progress(current);
        return current == TRUE ? 1 : current == FALSE ? 0 : -1;
    }

    /**
     * Decides the formula when the trace has deadlocked: the current state repeats for ever, so every temporal
     * operator's value is that of its operand on this state ({@code X f} is f, {@code l U<=k r} is r). Same answer as
     * feeding the repeated state until the bounds run out, without the iterations.
     *
     * @return 1 when the formula holds, 0 when it does not
     */
    public int decideOnRepeatedState(IntPredicate propositions) {
        state = propositions;
        epoch++;
        if (epoch == Integer.MAX_VALUE) {
            java.util.Arrays.fill(stamp, 0);
            epoch = 1;
        }
        boolean v = constant(current);
        current = v ? TRUE : FALSE;
        return v ? 1 : 0;
    }

    private boolean constant(Node n) {
        if (n instanceof Until u) {
            return constant(u.right);
        } else if (n instanceof Ap a) {
            return ap(a.index);
        } else if (n instanceof Const c) {
            return c.value;
        } else if (n instanceof Not x) {
            return !constant(x.operand);
        } else if (n instanceof And a) {
            return constant(a.left) && constant(a.right);
        } else if (n instanceof Or o) {
            return constant(o.left) || constant(o.right);
        }
        return constant(((Next) n).operand);
    }

    private boolean ap(int i) {
        if (stamp[i] != epoch) {
            stamp[i] = epoch;
            value[i] = state.test(i);
        }
        return value[i];
    }

    private Node progress(Node n) {
        if (n instanceof Until u) {
            Node r = progress(u.right);
            if (r == TRUE || u.bound == 0) {
                return r;
            }
            Node l = progress(u.left);
            if (l == FALSE) {
                return r;
            }
            Node rest = l == TRUE ? u.chain[u.bound - 1] : and(l, u.chain[u.bound - 1]);
            return r == FALSE ? rest : or(r, rest);
        } else if (n instanceof Ap a) {
            return ap(a.index) ? TRUE : FALSE;
        } else if (n instanceof Const) {
            return n;
        } else if (n instanceof Not x) {
            Node p = progress(x.operand);
            return p == TRUE ? FALSE : p == FALSE ? TRUE : new Not(p);
        } else if (n instanceof And a) {
            Node l = progress(a.left);
            return l == FALSE ? FALSE : and(l, progress(a.right));
        } else if (n instanceof Or o) {
            Node l = progress(o.left);
            return l == TRUE ? TRUE : or(l, progress(o.right));
        }
        return ((Next) n).operand;
    }

    private static Node and(Node l, Node r) {
        if (l == FALSE || r == FALSE) {
            return FALSE;
        }
        return l == TRUE ? r : r == TRUE ? l : new And(l, r);
    }

    private static Node or(Node l, Node r) {
        if (l == TRUE || r == TRUE) {
            return TRUE;
        }
        return l == FALSE ? r : r == FALSE ? l : new Or(l, r);
    }

    public int propositionCount() {
        return propositionCount;
    }
}
