package eu.brain.iot.edge.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** What became of an {@link EdgeCommand}: accepted by the device, or rejected with the reason. */
public class CommandOutcome extends BrainIoTEvent {

    /** The command's {@link EdgeCommand#commandId}. */
    public String commandId;
    public String deviceId;
    /** The command's simple class name, for example {@code GoToCommand}. */
    public String command;
    public boolean accepted;
    /** Why it was rejected (what the device or the edge said), {@code null} when accepted. */
    public String reason;
    /** The HTTP status the device answered, 0 when no answer came (or the edge refused the command itself). */
    public int status;
    /** The id of the mission the robot queued, when it queued one; {@code null} otherwise. */
    public Long missionId;
}
