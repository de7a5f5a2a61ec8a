package eu.brain.iot.bip.smc.stats;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;

import org.apache.commons.statistics.distribution.BetaDistribution;
import org.junit.jupiter.api.Test;

/**
 * The hand-written Clopper–Pearson interval and the regularised incomplete beta function under it agree with Apache
 * Commons Statistics (a test dependency only: the model checker has no runtime dependency) over a grid of sample
 * counts, successes and confidence levels, from one trace to millions, at the edges (no or every success) and in
 * the middle.
 */
class BoundsTest {

    private static final long[] SAMPLES = {1, 2, 3, 5, 10, 30, 100, 201, 1_000, 6_623, 26_492, 100_000, 1_000_000};
    private static final double[] ALPHAS = {0.001, 0.01, 0.02, 0.05, 0.1, 0.2};
    private static final double[] SHAPES = {0.5, 1, 2, 3.5, 10, 50, 201, 1_000, 26_492, 500_000};
    private static final double[] POINTS = {1e-9, 1e-6, 1e-3, 0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 0.999, 1 - 1e-6};

    /** Absolute agreement of the bounds, and relative agreement where a bound is tiny (few successes, many traces). */
    private static final double ABSOLUTE = 1e-9;
    private static final double RELATIVE = 1e-6;
    /**
     * Agreement of I_x(a, b), a probability: 1e-12, looser as the shapes grow, since the prefactor is
     * exp(ln Γ(a+b) − ln Γ(a) − ln Γ(b) + ...), a difference of numbers about (a+b)·ln(a+b) whose rounding (about
     * 1e-16 of each) the exponential turns into a relative error: 4e-10 at a + b = 10⁶.
     */
    private static double cdfTolerance(double a, double b) {
        return 1e-12 * Math.max(1, (a + b) / 1_000);
    }

    @Test
    void clopperPearsonAgreesWithTheBetaQuantilesOfCommonsStatistics() {
        List<String> mismatches = new ArrayList<>();
        int points = 0;
        for (long n : SAMPLES) {
            for (long k : successes(n)) {
                for (double alpha : ALPHAS) {
                    double[] ours = Bounds.clopperPearson(k, n, alpha);
                    double lower = k == 0 ? 0 : BetaDistribution.of(k, n - k + 1).inverseCumulativeProbability(alpha / 2);
                    double upper = k == n ? 1
                            : BetaDistribution.of(k + 1, n - k).inverseCumulativeProbability(1 - alpha / 2);
                    check(mismatches, "lower", k, n, alpha, ours[0], lower);
                    check(mismatches, "upper", k, n, alpha, ours[1], upper);
                    assertThat(ours[0]).isLessThanOrEqualTo((double) k / n).isGreaterThanOrEqualTo(0);
                    assertThat(ours[1]).isGreaterThanOrEqualTo((double) k / n).isLessThanOrEqualTo(1);
                    points++;
                }
            }
        }
        assertThat(points).isGreaterThan(400);
        assertThat(mismatches).as("bounds that differ from Commons Statistics").isEmpty();
    }

    @Test
    void theRegularisedIncompleteBetaAgreesWithTheBetaDistributionOfCommonsStatistics() {
        List<String> mismatches = new ArrayList<>();
        for (double a : SHAPES) {
            for (double b : SHAPES) {
                BetaDistribution reference = BetaDistribution.of(a, b);
                for (double x : POINTS) {
                    double ours = Bounds.regularizedBeta(x, a, b);
                    double theirs = reference.cumulativeProbability(x);
                    if (!(Math.abs(ours - theirs) <= cdfTolerance(a, b))) {
                        mismatches.add(String.format(Locale.ROOT, "I_%s(%s, %s) = %.17g, Commons Statistics %.17g",
                                x, a, b, ours, theirs));
                    }
                }
            }
        }
        assertThat(mismatches).as("values that differ from Commons Statistics").isEmpty();
    }

    /** No success, one, two, a tenth, a half, all but one, all. */
    private static TreeSet<Long> successes(long n) {
        TreeSet<Long> ks = new TreeSet<>(List.of(0L, 1L, 2L, n / 10, n / 2, n - 1, n));
        ks.removeIf(k -> k < 0 || k > n);
        return ks;
    }

    private static void check(List<String> mismatches, String bound, long k, long n, double alpha, double ours,
            double theirs) {
        double error = Math.abs(ours - theirs);
        if (!(error <= ABSOLUTE && error <= Math.max(RELATIVE * Math.abs(theirs), Double.MIN_NORMAL))) {
            mismatches.add(String.format(Locale.ROOT, "%s of %d of %d at alpha %s: %.17g, Commons Statistics %.17g",
                    bound, k, n, alpha, ours, theirs));
        }
    }
}
