package eu.brain.iot.robotsim.world;

/**
 * The tunable physics of the world.
 *
 * @param seed          decides who wins when two robots want the same cell in the same step
 * @param pickSteps     steps the corkscrew lift takes
 * @param placeSteps    steps putting a cart down takes
 * @param deadlockSteps steps robots must wait on each other in a cycle before it counts as a deadlock
 * @param doorOpenSteps steps a door takes to open; negative means "as the map says"
 */
public record SimRules(long seed, int pickSteps, int placeSteps, int deadlockSteps, int doorOpenSteps) {
    public static final SimRules DEFAULT = new SimRules(1L, 2, 2, 4, -1);

    public SimRules {
        if (pickSteps < 1 || placeSteps < 1 || deadlockSteps < 1) {
            throw new IllegalArgumentException("pickSteps, placeSteps and deadlockSteps must be >= 1");
        }
    }

    public SimRules withSeed(long newSeed) {
        return new SimRules(newSeed, pickSteps, placeSteps, deadlockSteps, doorOpenSteps);
    }

    public SimRules withDoorOpenSteps(int steps) {
        return new SimRules(seed, pickSteps, placeSteps, deadlockSteps, steps);
    }
}
