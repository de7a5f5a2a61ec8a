package eu.brain.iot.edge.api;

/** A robot's mission failed or was cancelled. */
public class MissionFailed extends RobotEvent {

    public long missionId;
    /** {@code goto}, {@code pick} or {@code place}. */
    public String missionType;
    /** Why, as the robot says: for example {@code cancelled} or {@code no cart at (9,7)}. */
    public String reason;
    public Integer goalX;
    public Integer goalY;
}
