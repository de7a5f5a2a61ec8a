package eu.brain.iot.bip.smc.query;

/**
 * A bounded LTL formula over atomic propositions (indices into the query's proposition list). Bounds count steps;
 * a bound may be a swept parameter ({@code paramIndex} &ge; 0).
 */
public sealed interface Formula {

    record Const(boolean value) implements Formula {
    }

    record Ap(int index) implements Formula {
    }

    record Not(Formula operand) implements Formula {
    }

    record And(Formula left, Formula right) implements Formula {
    }

    record Or(Formula left, Formula right) implements Formula {
    }

    record Next(Formula operand) implements Formula {
    }

    /** {@code left U<=bound right}; {@code F<=t f} is {@code true U<=t f}, {@code G<=t f} is {@code !F<=t !f}. */
    record Until(Formula left, Formula right, Bound bound) implements Formula {
    }

    /** A step bound: a number, or a swept parameter. */
    record Bound(int value, int paramIndex) {
        public int resolve(double[] params) {
            return paramIndex < 0 ? value : (int) params[paramIndex];
        }
    }
}
