package eu.brain.iot.edge.api;

/** Cancel a robot's mission: the given one, or else the running (else first queued) mission of that type. */
public class CancelMissionCommand extends EdgeCommand {

    /** {@code goto} (the default when {@code null}), {@code pick} or {@code place}. */
    public String missionType;
    /** The mission to cancel, or {@code null}. */
    public Long missionId;
}
