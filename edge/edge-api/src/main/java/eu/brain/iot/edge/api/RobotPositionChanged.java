package eu.brain.iot.edge.api;

/**
 * A robot stands on another grid cell (or was seen for the first time). Published once per change, not per poll.
 */
public class RobotPositionChanged extends RobotEvent {

    /** Grid cell (QR tag) the robot stands on. */
    public int x;
    public int y;
    /** {@code N}, {@code E}, {@code S} or {@code W}. */
    public String heading;
    /** Area code of the cell: 0 corridor, 1 docking, 2 unload, 3 storage, 5 doorway. */
    public int area;
    /** {@code running} or {@code stopped}. */
    public String state;
    /** The cell before, or {@code null} when the robot is seen for the first time. */
    public Integer previousX;
    public Integer previousY;
}
