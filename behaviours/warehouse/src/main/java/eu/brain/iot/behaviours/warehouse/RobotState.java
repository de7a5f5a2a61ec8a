package eu.brain.iot.behaviours.warehouse;

/**
 * One robot as the edge's device model shows it now.
 *
 * @param id           the fleet's id, for example {@code robot1}
 * @param cell         where it stands
 * @param heading      {@code N}, {@code E}, {@code S} or {@code W}
 * @param area         the area code of its cell (0 corridor, 1 docking, 2 unload, 3 storage, 5 doorway)
 * @param running      whether it moves (the fleet's {@code state} is {@code running})
 * @param detect       its front sensor: 0 nothing, 1 a robot, 2 a closed door
 * @param cart         the cart it carries, or {@code null}
 * @param missionId    its running mission, else the next queued, else the last ended; {@code null} before any
 * @param missionType  {@code goto}, {@code pick} or {@code place} (of that mission)
 * @param missionState {@code queued}, {@code running}, {@code finished} or {@code failed}
 * @param goal         the goal of that mission when it is a {@code goto}, else {@code null}
 * @param reachable    whether what the model shows of it is current: the last poll of it answered (its status is not
 *                     {@code UNREACHABLE}) and, for a robot another node of the fabric polls, that node reported it
 *                     lately (not {@code STALE}: a node that died leaves its robots' last values behind, which a
 *                     robot behaviour taking them over must not act on)
 */
public record RobotState(String id, Cell cell, String heading, int area, boolean running, int detect, String cart,
        Long missionId, String missionType, String missionState, Cell goal, boolean reachable) {

    /** {@link #detect}: the front sensor sees nothing. */
    public static final int DETECTS_NOTHING = 0;
    /** {@link #detect}: a robot in the cell in front. */
    public static final int DETECTS_ROBOT = 1;
    /** {@link #detect}: a closed (or not yet open) door in the cell in front. */
    public static final int DETECTS_DOOR = 2;
    /** {@link #missionType}: a go-to. */
    public static final String GOTO = "goto";
    /** {@link #missionState}: the mission ended as asked. */
    public static final String FINISHED = "finished";
    /** {@link #missionState}: the mission ended without reaching its end (refused by the fleet, no path, cancelled). */
    public static final String FAILED = "failed";

    /** @return whether its front sensor sees a robot in the cell in front */
    public boolean facesRobot() {
        return detect == DETECTS_ROBOT;
    }

    /** @return whether its front sensor sees a door that is not open in the cell in front */
    public boolean facesDoor() {
        return detect == DETECTS_DOOR;
    }

    /** @return whether it has no mission waiting or running (none yet, or the last one ended) */
    public boolean idle() {
        return missionState == null || FINISHED.equals(missionState) || FAILED.equals(missionState);
    }

    /** @return whether its running or next mission is a go-to to {@code to} */
    public boolean headingFor(Cell to) {
        return !idle() && GOTO.equals(missionType) && to.equals(goal);
    }

    /** @return the cell in front of it */
    public Cell ahead() {
        return cell.toward(heading);
    }

    public boolean carrying() {
        return cart != null;
    }
}
