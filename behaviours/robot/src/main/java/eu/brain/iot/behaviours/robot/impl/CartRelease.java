package eu.brain.iot.behaviours.robot.impl;

/**
 * When a robot without an errand may claim a cart: how the fleet is released towards the door.
 * <ul>
 * <li>{@link #waves(int) Waves} (robot-sim plans each go-to, the orchestrator resolves meetings): at most a wave of
 * robots go for carts at once, and none sets off while a robot of the wave still carries its cart, so the door is
 * crossed one way at a time.</li>
 * <li>{@link #continuous() Continuous} (the traffic planner drives): a robot claims a cart as soon as it is back at its
 * dock, whoever carries what. The planner's passage claims take the door one way at a time, and a queue on each
 * side keeps it busy: with waves, the whole fleet went down, then came back up, and the last robots of a wave
 * crossed an idle door alone (60x30, 30 robots: 518-553 carts per warehouse hour with waves as large as the fleet,
 * 638-697 released continuously, seeds 11 and 12).</li>
 * </ul>
 * Immutable: any thread.
 */
final class CartRelease {
    private final int wave;
    private final boolean whileCarrying;

    private CartRelease(int wave, boolean whileCarrying) {
        this.wave = Math.max(1, wave);
        this.whileCarrying = whileCarrying;
    }

    /** @param robots robots that may go for carts at once (at least 1) */
    static CartRelease waves(int robots) {
        return new CartRelease(robots, false);
    }

    /** Every robot back at its dock may claim a cart. */
    static CartRelease continuous() {
        return new CartRelease(Integer.MAX_VALUE, true);
    }

    /**
     * @param goingForCarts robots on their way to a cart now
     * @param anyCarrying   whether some robot carries a cart to storage now
     * @return whether a robot without an errand may claim a cart now
     */
    boolean open(long goingForCarts, boolean anyCarrying) {
        return (whileCarrying || !anyCarrying) && goingForCarts < wave;
    }

    @Override
    public String toString() {
        return whileCarrying ? "released continuously" : "waves of " + wave + " robots";
    }
}
