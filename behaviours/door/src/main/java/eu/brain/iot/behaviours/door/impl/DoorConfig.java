package eu.brain.iot.behaviours.door.impl;

/**
 * Configuration of the door behaviour's binding (PID {@value #PID}, a component property type; every value
 * optional). Times are warehouse time; {@code speed} is the fleet's speed factor (robot-sim's {@code --speed}).
 */
public @interface DoorConfig {

    String PID = "eu.brain.iot.behaviours.door";

    /** The fleet's speed factor: warehouse time runs this many times faster than wall-clock time. */
    double speed() default 1.0;

    /** Warehouse time between two looks at the doors (the edge's poll period at speed 1), in milliseconds. */
    long poll_period_ms() default 500;

    /** Looks in a row with no robot near an open door before the binding closes it. */
    int close_after_polls() default 6;

    /** Cells (steps on the grid, ignoring walls) around a door within which a robot keeps it open. */
    int near_cells() default 3;
}
