package eu.brain.iot.scenario;

import java.nio.file.Path;
import java.util.List;

/**
 * What a scenario run was asked to do (the command line, checked).
 *
 * @param root          the repository root: node/target/fabric-node.jar, node/config, repository/target
 * @param map           a map file, or null for the paper's warehouse (or a generated one)
 * @param generate      the generated warehouse's size, or null
 * @param seed          robot-sim's seed (and the generated map's)
 * @param speed         robot-sim's speed factor: warehouse time runs this many times faster than wall time
 * @param waitLimitMs   REQ-2: the longest a robot may wait behind another robot (warehouse ms); also robot-sim's
 *                      deadlock threshold
 * @param deadlineMs    warehouse time after which an unfinished run ends and fails
 * @param faults        faults to inject, by warehouse time
 * @param runDir        the run's folder (node configuration, journal, logs, report)
 * @param report        where the JSON report goes
 * @param progressMs    wall time between two progress lines
 * @param behaviours    false: the node gets no behaviour repository (nothing installs behaviours; to see the judge
 *                      fail)
 * @param nodeConfigs   extra configuration files copied into the node's configuration folder
 * @param traffic       the robot behaviour's traffic planner drives the robots
 * @param fabric        the fabric the node joins, or null: the node runs alone
 */
record Options(Path root, Path map, Generate generate, long seed, double speed, long waitLimitMs, long deadlineMs,
               List<PlannedFault> faults, Path runDir, Path report, long progressMs, boolean behaviours,
               List<Path> nodeConfigs, boolean traffic, Fabric fabric) {

    /**
     * The fabric of nodes the run's node joins through an MQTT 5 broker (federation/README.md).
     *
     * @param broker the broker's URI, {@code tcp://host:port} or {@code ssl://host:port}
     * @param key    the fabric's signing key file, or null: a new key in the run's folder
     */
    record Fabric(String broker, Path key) {
        /** The fabric's name and the run's node's name in it. */
        static final String NAME = "warehouse";
        static final String NODE = "node1";
    }

    /** robot-sim's step: the paper's 0.5 s. */
    static final int STEP_MILLIS = 500;

    /** {@code robot-sim generate} options. */
    record Generate(int width, int height, int robots, int carts, int doors) {
    }

    /** The wait limit in steps, rounded up: robot-sim's {@code --deadlock-steps}. */
    int waitLimitSteps() {
        return (int) Math.max(1, (waitLimitMs + STEP_MILLIS - 1) / STEP_MILLIS);
    }

    /** The edge's poll period scaled to the speed: the paper's 0.5 s of warehouse time. */
    long pollPeriodMs() {
        return Math.max(1, Math.round(STEP_MILLIS / speed));
    }
}
