package eu.brain.iot.edge.api;

/** A robot's front sensor reports an obstacle (it stopped in front of a robot or a closed door). */
public class ObstacleDetected extends RobotEvent {

    public ObstacleKind kind;
    /** The raw sensor value: 1 a robot, 2 a door. */
    public int detect;
    /** Where the robot stands, and which way it faces. */
    public int x;
    public int y;
    public String heading;
}
