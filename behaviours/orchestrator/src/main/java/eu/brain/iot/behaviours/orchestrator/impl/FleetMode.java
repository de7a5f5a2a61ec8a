package eu.brain.iot.behaviours.orchestrator.impl;

/**
 * How the robot behaviour drives the fleet, read by the orchestrator from the robot behaviour's own configuration
 * (PID {@value #PID}: one setting for both, so that they never disagree; every value optional).
 */
public @interface FleetMode {

    /** The robot behaviour's configuration PID ({@code RobotConfig.PID} in the robot bundle). */
    String PID = "eu.brain.iot.behaviours.robot";

    /**
     * Whether the fleet's traffic planner drives the robots: then every go-to is a leg of a reserved path that the
     * robot behaviour sends, and the orchestrator sends no robot anywhere itself ({@link CollisionGeometry}).
     */
    boolean traffic() default false;
}
