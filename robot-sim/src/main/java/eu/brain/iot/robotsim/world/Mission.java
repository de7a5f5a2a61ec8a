package eu.brain.iot.robotsim.world;

/**
 * One order given to a robot. Owned by the thread that owns the {@link World}; other threads see missions only
 * through published views.
 */
public final class Mission {
    private final long id;
    private final MissionType type;
    private final int goalX;
    private final int goalY;
    private MissionState state = MissionState.QUEUED;
    private String reason;

    Mission(long id, MissionType type, int goalX, int goalY) {
        this.id = id;
        this.type = type;
        this.goalX = goalX;
        this.goalY = goalY;
    }

    public long id() {
        return id;
    }

    public MissionType type() {
        return type;
    }

    /** Goal column of a GOTO mission, -1 for pick and place. */
    public int goalX() {
        return goalX;
    }

    /** Goal row of a GOTO mission, -1 for pick and place. */
    public int goalY() {
        return goalY;
    }

    public MissionState state() {
        return state;
    }

    /** Why the mission failed, or null. */
    public String reason() {
        return reason;
    }

    void start() {
        state = MissionState.RUNNING;
    }

    void finish() {
        state = MissionState.FINISHED;
    }

    void fail(String why) {
        state = MissionState.FAILED;
        reason = why;
    }
}
