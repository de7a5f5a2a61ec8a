package eu.brain.iot.behaviours.robot.impl;

/**
 * Configuration of the robot behaviour's binding and extern functions (PID {@value #PID}, a component property
 * type; every value optional). Times are warehouse time; {@code speed} says how much faster than wall-clock time
 * the fleet runs (robot-sim's {@code --speed}), so that the binding looks at the robots once per poll of the
 * warehouse, whatever the speed.
 */
public @interface RobotConfig {

    /** The configuration PID, shared by {@link RobotBinding} and {@link RobotExterns}. */
    String PID = "eu.brain.iot.behaviours.robot";

    /** The fleet's speed factor: warehouse time runs this many times faster than wall-clock time. */
    double speed() default 1.0;

    /** Warehouse time between two looks at every robot (the edge's poll period at speed 1), in milliseconds. */
    long poll_period_ms() default 500;

    /**
     * Polls a robot stays stopped behind another robot before the binding reports it (a robot-in-front,
     * {@code fromUnloadObstacle} with {@code isObstacle}): 2 polls = 1 s, as the requirements gate's environment
     * ({@code patience} in WarehouseEnvironment.bip). Longer patience leaves too little of REQ-2's 10 s limit on a
     * wait behind a robot for the orchestrator to resolve a head-on meeting.
     */
    int patience_polls() default 2;

    /**
     * Robots that go for carts at once: the door policy fetches carts in waves of at most this many robots, all
     * crossing the door down, then all crossing it back with their carts ({@code CartRelease}). A larger wave
     * uses the door better and crowds the unload area and storage more: in the 60x30 warehouse (30 robots) waves of
     * 6 passed about 330 carts per warehouse hour with one wait of 10.5 s in 2 seeds of 3 (REQ-2's limit is 10 s),
     * waves of 4 about 230 with every wait under 7.5 s in 4 seeds of 4 (BENCHMARKS.md, "Warehouse scenario").
     */
    int wave_robots() default 4;

    /** How often a refused command is sent again before the errand is planned anew. */
    int command_retries() default 3;

    /**
     * Whether the fleet's traffic planner drives the robots (legs along reserved paths, {@code TrafficControl}); when
     * false, robot-sim plans each go-to itself and the orchestrator resolves meetings, with waves of
     * {@code wave.robots}.
     */
    boolean traffic() default false;

    /**
     * With the traffic planner: robots per door that may be out on an errand for a cart at once, going for one or
     * carrying it (released continuously, each robot as soon as it is back at its dock: {@code CartRelease}).
     */
    int traffic_release_robots_per_door() default CartRelease.ROBOTS_PER_DOOR;

    /** Steps of 0.5 s the traffic planner reserves ahead (longer than the map's longest one-cell passage). */
    int traffic_window() default 16;
}
