package eu.brain.iot.bip.smc.stats;

/**
 * Sample counts and confidence intervals for a Bernoulli probability: the Chernoff–Hoeffding (Okamoto) bound and
 * the exact Clopper–Pearson interval (by bisection on the regularised incomplete beta function).
 */
public final class Bounds {

    private Bounds() {
    }

    /** @return n with P(|p̂ − p| &ge; ε) &le; δ for every p: ⌈ln(2/δ) / (2ε²)⌉ (Okamoto) */
    public static long okamoto(double epsilon, double delta) {
        if (!(epsilon > 0 && epsilon < 1 && delta > 0 && delta < 1)) {
            throw new IllegalArgumentException("epsilon and delta must be between 0 and 1 (exclusive)");
        }
        return (long) Math.ceil(Math.log(2 / delta) / (2 * epsilon * epsilon));
    }

    /** @return the two-sided Clopper–Pearson interval {lower, upper} at confidence 1 − alpha for k of n */
    public static double[] clopperPearson(long k, long n, double alpha) {
        if (n == 0) {
            return new double[] {0, 1};
        }
        double lower = k == 0 ? 0 : betaQuantile(alpha / 2, k, n - k + 1);
        double upper = k == n ? 1 : betaQuantile(1 - alpha / 2, k + 1, n - k);
        return new double[] {lower, upper};
    }

    /** @return x with I_x(a, b) = p */
    static double betaQuantile(double p, double a, double b) {
        double lo = 0;
        double hi = 1;
        for (int i = 0; i < 100; i++) {
            double mid = (lo + hi) / 2;
            if (regularizedBeta(mid, a, b) < p) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return (lo + hi) / 2;
    }

    /** The regularised incomplete beta function I_x(a, b), by Lentz's continued fraction. */
    static double regularizedBeta(double x, double a, double b) {
        if (x <= 0) {
            return 0;
        }
        if (x >= 1) {
            return 1;
        }
        double front = Math.exp(logGamma(a + b) - logGamma(a) - logGamma(b) + a * Math.log(x) + b * Math.log1p(-x));
        if (x < (a + 1) / (a + b + 2)) {
            return front * continuedFraction(x, a, b) / a;
        }
        return 1 - Math.exp(logGamma(a + b) - logGamma(a) - logGamma(b) + b * Math.log1p(-x) + a * Math.log(x))
                * continuedFraction(1 - x, b, a) / b;
    }

    private static double continuedFraction(double x, double a, double b) {
        final double tiny = 1e-300;
        double c = 1;
        double d = 1 - (a + b) * x / (a + 1);
        d = Math.abs(d) < tiny ? tiny : d;
        d = 1 / d;
        double f = d;
        for (int m = 1; m < 10_000; m++) {
            int m2 = 2 * m;
            double num = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
            d = 1 + num * d;
            d = Math.abs(d) < tiny ? tiny : d;
            c = 1 + num / c;
            c = Math.abs(c) < tiny ? tiny : c;
            d = 1 / d;
            f *= d * c;
            num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
            d = 1 + num * d;
            d = Math.abs(d) < tiny ? tiny : d;
            c = 1 + num / c;
            c = Math.abs(c) < tiny ? tiny : c;
            d = 1 / d;
            double delta = d * c;
            f *= delta;
            if (Math.abs(delta - 1) < 1e-15) {
                break;
            }
        }
        return f;
    }

    /** ln Γ(x) for x &gt; 0 (Lanczos, g = 7, 9 terms). */
    static double logGamma(double x) {
        final double[] g = {0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313,
            -176.61502916214059, 12.507343278686905, -0.13857109526572012, 9.9843695780195716e-6,
            1.5056327351493116e-7};
        if (x < 0.5) {
            return Math.log(Math.PI / Math.abs(Math.sin(Math.PI * x))) - logGamma(1 - x);
        }
        x -= 1;
        double a = g[0];
        double t = x + 7.5;
        for (int i = 1; i < 9; i++) {
            a += g[i] / (x + i);
        }
        return 0.5 * Math.log(2 * Math.PI) + (x + 0.5) * Math.log(t) - t + Math.log(a);
    }
}
