package eu.brain.iot.bip.smc.query;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.model.Pos;

/**
 * A resolved PBLTL query: {@code P=? [φ]} (estimate) or {@code P>=θ [φ]} / {@code P<=θ [φ]} (test), its atomic
 * propositions (indices of {@link Formula.Ap}) and its parameter sweeps.
 *
 * @param name the requirement's name (a file's {@code NAME:}, else the query text)
 * @param justification the comment lines above it in a requirements file, or ""
 */
public record Query(String name, String text, Kind kind, double threshold, Formula formula, List<Term> propositions,
        List<Sweep> sweeps, Pos pos, String justification) {

    public enum Kind {
        ESTIMATE("P=?"), AT_LEAST("P>="), AT_MOST("P<=");

        public final String symbol;

        Kind(String symbol) {
            this.symbol = symbol;
        }
    }

    public Query {
        propositions = List.copyOf(propositions);
        sweeps = List.copyOf(sweeps);
    }

    /** A swept parameter, {@code name = from:to:step}, inclusive. */
    public record Sweep(String name, double from, double to, double step, boolean integral) {
        public List<Double> values() {
            List<Double> values = new ArrayList<>();
            long count = (long) Math.floor((to - from) / step + 1e-9) + 1;
            for (long i = 0; i < count; i++) {
                values.add(integral ? Math.rint(from + i * step) : from + i * step);
            }
            return values;
        }
    }

    /** @return every combination of the sweeps' values (one empty point without sweeps), first sweep slowest */
    public List<double[]> points() {
        List<double[]> points = new ArrayList<>();
        points.add(new double[0]);
        for (Sweep s : sweeps) {
            List<double[]> next = new ArrayList<>();
            for (double[] p : points) {
                for (double v : s.values()) {
                    double[] q = java.util.Arrays.copyOf(p, p.length + 1);
                    q[p.length] = v;
                    next.add(q);
                }
            }
            points = next;
        }
        return points;
    }

    public boolean qualitative() {
        return kind != Kind.ESTIMATE;
    }

    /** @return the steps a trace needs for the formula's value to be known (its horizon) */
    public int horizon(double[] params) {
        return horizon(formula, params);
    }

    private static int horizon(Formula f, double[] params) {
        if (f instanceof Formula.Not n) {
            return horizon(n.operand(), params);
        } else if (f instanceof Formula.And a) {
            return Math.max(horizon(a.left(), params), horizon(a.right(), params));
        } else if (f instanceof Formula.Or o) {
            return Math.max(horizon(o.left(), params), horizon(o.right(), params));
        } else if (f instanceof Formula.Next n) {
            return 1 + horizon(n.operand(), params);
        } else if (f instanceof Formula.Until u) {
            return u.bound().resolve(params) + Math.max(horizon(u.left(), params), horizon(u.right(), params));
        }
        return 0;
    }
}
