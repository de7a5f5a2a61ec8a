package eu.brain.iot.robotsim.world;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;

/**
 * A simulated robot. Owned by the world's owner thread (the step thread of a running simulator); never read
 * directly by HTTP threads, which see {@code RobotView}s published after each change.
 */
public final class Robot {
    private static final int[] NO_PATH = new int[0];
    static final int HISTORY = 16;

    private final int index;
    private final String id;
    int x;
    int y;
    Heading heading = Heading.N;
    /** True when the robot works on a mission and is not held up by its front sensor. */
    boolean running;
    /** 0 nothing in front, 1 a robot, 2 a closed door. */
    int detect;
    /** Index of the carried cart, -1 when none. */
    int carried = -1;
    final Deque<Mission> queue = new ArrayDeque<>();
    /** The most recently ended missions, newest first, for query_state. */
    private final Deque<Mission> history = new ArrayDeque<>();
    Mission current;
    /** Cells still to travel for the current GOTO (cell indices), consumed from pathPos. */
    int[] path = NO_PATH;
    int pathPos;
    /** Steps left of the current pick or place (the corkscrew lift takes time). */
    int actionLeft;
    /** Robot (index) whose cell the front sensor sees this step, -1 when none. */
    int blockedBy = -1;
    boolean wasBlockedByRobot;
    int cycleSteps;
    boolean deadlockCounted;
    long nearMisses;
    long deadlocks;
    /** Steps spent stopped behind another robot ({@code detect} 1), all waits together. */
    long waitSteps;
    /** Length in steps of the wait going on now, 0 when not waiting behind a robot. */
    long waitingSteps;
    /** The longest single wait behind another robot, in steps (the one going on now included). */
    long longestWaitSteps;
    /** Waits behind another robot that have ended (the robot moved on, got new orders or went offline). */
    long waitsEnded;
    boolean offline;
    /** Missions that ended: finished, failed (a precondition or no path), cancelled. */
    long missionsFinished;
    long missionsFailed;
    long missionsCancelled;

    Robot(int index, String id, int x, int y) {
        this.index = index;
        this.id = id;
        this.x = x;
        this.y = y;
    }

    public int index() {
        return index;
    }

    public String id() {
        return id;
    }

    public int x() {
        return x;
    }

    public int y() {
        return y;
    }

    public Heading heading() {
        return heading;
    }

    public boolean running() {
        return running;
    }

    public int detect() {
        return detect;
    }

    /** Index of the carried cart, -1 when none. */
    public int carried() {
        return carried;
    }

    public long nearMisses() {
        return nearMisses;
    }

    public long deadlocks() {
        return deadlocks;
    }

    /** Steps spent stopped behind another robot, all waits together. */
    public long waitSteps() {
        return waitSteps;
    }

    /** Length in steps of the wait behind another robot going on now, 0 when none. */
    public long waitingSteps() {
        return waitingSteps;
    }

    /** The longest single wait behind another robot so far, in steps. */
    public long longestWaitSteps() {
        return longestWaitSteps;
    }

    /** Waits behind another robot that have ended. */
    public long waitsEnded() {
        return waitsEnded;
    }

    public long missionsFinished() {
        return missionsFinished;
    }

    /** Missions that failed by themselves (a precondition that did not hold when they started, no path). */
    public long missionsFailed() {
        return missionsFailed;
    }

    public long missionsCancelled() {
        return missionsCancelled;
    }

    public boolean offline() {
        return offline;
    }

    /** The mission to show: the running one, else the next queued one, else the last that ended; or null. */
    public Mission shownMission() {
        if (current != null) {
            return current;
        }
        Mission next = queue.peekFirst();
        return next != null ? next : history.peekFirst();
    }

    public Mission current() {
        return current;
    }

    public List<Mission> queued() {
        return List.copyOf(queue);
    }

    void setPath(int[] cells) {
        path = cells;
        pathPos = 0;
    }

    void clearPath() {
        path = NO_PATH;
        pathPos = 0;
    }

    boolean hasPathLeft() {
        return pathPos < path.length;
    }

    int nextCell() {
        return path[pathPos];
    }

    /** Missions that ended, newest first (at most {@value #HISTORY}). */
    public List<Mission> history() {
        return List.copyOf(history);
    }

    void remember(Mission ended) {
        if (ended.state() == MissionState.FINISHED) {
            missionsFinished++;
        } else if ("cancelled".equals(ended.reason())) {
            missionsCancelled++;
        } else {
            missionsFailed++;
        }
        history.addFirst(ended);
        if (history.size() > HISTORY) {
            history.removeLast();
        }
    }

    /** Forgets the current mission (the caller has remembered it). */
    void endCurrent() {
        current = null;
        clearPath();
        actionLeft = 0;
    }
}
