package eu.brain.iot.bip.smc.stats;

/**
 * Wald's sequential probability ratio test of H0: p &ge; θ + δ' against H1: p &le; θ − δ' (δ' the half-width of the
 * indifference region), with P(accept H1 | H0) &le; α and P(accept H0 | H1) &le; β. Fed samples in trace order,
 * so its decision does not depend on the number of sampling threads. Owned by one thread.
 */
public final class Sprt {

    /** The test's state. */
    public enum Decision { UNDECIDED, ACCEPT_H0, ACCEPT_H1 }

    private final double successStep;
    private final double failureStep;
    private final double acceptH1;
    private final double acceptH0;
    private double llr;
    private long samples;
    private long successes;
    private Decision decision = Decision.UNDECIDED;

    public Sprt(double theta, double indifference, double alpha, double beta) {
        double p0 = Math.min(1, theta + indifference);
        double p1 = Math.max(0, theta - indifference);
        this.successStep = Math.log(p1 / p0);
        this.failureStep = Math.log((1 - p1) / (1 - p0));
        this.acceptH1 = Math.log((1 - beta) / alpha);
        this.acceptH0 = Math.log(beta / (1 - alpha));
    }

    /** Adds one sample; @return the decision so far */
    public Decision add(boolean success) {
        if (decision != Decision.UNDECIDED) {
            return decision;
        }
        samples++;
        if (success) {
            successes++;
        }
        llr += success ? successStep : failureStep;
        if (llr >= acceptH1) {
            decision = Decision.ACCEPT_H1;
        } else if (llr <= acceptH0) {
            decision = Decision.ACCEPT_H0;
        }
        return decision;
    }

    public Decision decision() {
        return decision;
    }

    public long samples() {
        return samples;
    }

    public long successes() {
        return successes;
    }
}
