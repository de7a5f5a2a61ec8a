package eu.brain.iot.edge.api;

/** What a robot's front sensor reports ({@code detect} in the robot's answer). */
public enum ObstacleKind {
    /** {@code detect = 1}: another robot is in the next cell. */
    ROBOT,
    /** {@code detect = 2}: the next cell is a door that is not open. */
    DOOR
}
