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
 * @param fabric        the fabric the nodes join, or null: one node runs alone
 * @param nodes         how many fabric nodes (1..{@value #MAX_NODES}); with 2 or more {@code fabric} is never null
 */
record Options(Path root, Path map, Generate generate, long seed, double speed, long waitLimitMs, long deadlineMs,
               List<PlannedFault> faults, Path runDir, Path report, long progressMs, boolean behaviours,
               List<Path> nodeConfigs, boolean traffic, Fabric fabric, int nodes) {

    /** The most nodes a run starts (as node/bin/fabric-nodes.sh). */
    static final int MAX_NODES = 20;

    /**
     * The fabric of nodes the run's nodes join through an MQTT 5 broker (federation/README.md).
     *
     * @param broker the broker's URI, {@code tcp://host:port} or {@code ssl://host:port}, or null: the run starts the
     *               embedded broker (broker/) on a free port of 127.0.0.1
     * @param key    the fabric's signing key file, or null: a new key in the run's folder
     * @param name   the fabric's name (its topic tree's root): {@value #NAME} for one node, unique per run for several
     */
    record Fabric(String broker, Path key, String name) {
        /** The fabric's name with one node, and that node's name in it. */
        static final String NAME = "warehouse";
        static final String NODE = "node1";

        /** One node's fabric: named {@value #NAME}. */
        Fabric(String broker, Path key) {
            this(broker, key, NAME);
        }
    }

    /** Node K's name (K from 1): {@code nodeK}. */
    static String nodeName(int k) {
        return "node" + k;
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

    /**
     * Polls of every robot per step of robot-sim (the paper's 0.5 s of warehouse time): with two, a leg's end reaches
     * the robot behaviour half a step sooner on average, and the robot waits that much less for its next leg
     * (BENCHMARKS.md, "With the traffic planner", has the figures of one and two). The robot behaviour's own look
     * stays once per 0.5 s of warehouse time, and it reacts at once to what the edge reports.
     */
    static final int POLLS_PER_STEP = 2;

    /** The edge's poll period scaled to the speed: {@value #POLLS_PER_STEP} polls per step. */
    long pollPeriodMs() {
        return Math.max(1, Math.round(STEP_MILLIS / speed / POLLS_PER_STEP));
    }
}
