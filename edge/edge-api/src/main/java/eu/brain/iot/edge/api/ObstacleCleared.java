package eu.brain.iot.edge.api;

/** A robot's front sensor no longer reports the obstacle of the previous {@link ObstacleDetected}. */
public class ObstacleCleared extends RobotEvent {

    /** The obstacle that went away. */
    public ObstacleKind kind;
    public int x;
    public int y;
}
