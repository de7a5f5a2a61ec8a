package eu.brain.iot.robotsim.world;

/** Where a mission is in its life; a cancelled mission ends as FAILED with reason "cancelled". */
public enum MissionState {
    QUEUED, RUNNING, FINISHED, FAILED;

    public String jsonName() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }

    public boolean ended() {
        return this == FINISHED || this == FAILED;
    }
}
