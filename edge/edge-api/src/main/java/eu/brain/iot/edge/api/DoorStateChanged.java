package eu.brain.iot.edge.api;

/** A door changed state: {@code closed}, {@code opening}, {@code open} or {@code closing}. */
public class DoorStateChanged extends eu.brain.iot.eventing.api.BrainIoTEvent {

    public String doorId;
    public String state;
    /** The state before, or {@code null} when the door is seen for the first time. */
    public String previousState;
    public int x;
    public int y;
}
