package eu.brain.iot.bip.smc;

/**
 * The exact bounded-reachability probabilities of BirthDeath.bip under the SMC semantics, by dynamic programming over
 * its states (n, place TOP, full, visits capped): at each step the candidates are the population's internal step
 * (when full in L, or in TOP) and the enabled interactions birth (n &lt; 4, in L) and death (n &gt; 0, in L), each
 * with probability 1 / (number of candidates).
 */
final class BirthDeathExact {

    private BirthDeathExact() {
    }

    /** @return P(within t steps, visits reaches k) */
    static double probabilityOfVisits(int k, int t) {
        // index: n (0..4) x top (0..1) x full (0..1) x visits (0..k)
        double[][][][] p = new double[5][2][2][k + 1];
        p[0][0][0][0] = 1;
        double reached = 0;
        for (int step = 0; step < t; step++) {
            double[][][][] q = new double[5][2][2][k + 1];
            for (int n = 0; n < 5; n++) {
                for (int top = 0; top < 2; top++) {
                    for (int full = 0; full < 2; full++) {
                        for (int v = 0; v < k; v++) {
                            double mass = p[n][top][full][v];
                            if (mass == 0) {
                                continue;
                            }
                            boolean internal = top == 1 || full == 1;
                            boolean birth = top == 0 && n < 4;
                            boolean death = top == 0 && n > 0;
                            int count = (internal ? 1 : 0) + (birth ? 1 : 0) + (death ? 1 : 0);
                            double each = mass / count;
                            if (internal) {
                                if (top == 1) {
                                    q[n][0][full][v] += each;
                                } else {
                                    q[n][1][0][Math.min(k, v + 1)] += each;
                                }
                            }
                            if (birth) {
                                q[n + 1][0][n + 1 == 4 ? 1 : 0][v] += each;
                            }
                            if (death) {
                                q[n - 1][0][full][v] += each;
                            }
                        }
                    }
                }
            }
            for (int n = 0; n < 5; n++) {
                for (int top = 0; top < 2; top++) {
                    for (int full = 0; full < 2; full++) {
                        reached += q[n][top][full][k];
                        q[n][top][full][k] = 0;
                    }
                }
            }
            p = q;
        }
        return reached;
    }
}
