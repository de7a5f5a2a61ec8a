package eu.brain.iot.edge.api;

/** A robot finished a mission (go to a cell, pick a cart, place a cart). */
public class MissionFinished extends RobotEvent {

    /** The mission id the robot gave when the command was accepted ({@link CommandOutcome#missionId}). */
    public long missionId;
    /** {@code goto}, {@code pick} or {@code place}. */
    public String missionType;
    /** The goal cell of a {@code goto}, else {@code null}. */
    public Integer goalX;
    public Integer goalY;
}
