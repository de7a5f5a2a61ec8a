package eu.brain.iot.robotsim.world;

/** A door lets robots through only when OPEN. CLOSING waits for its cell to be clear of robots. */
public enum DoorState {
    CLOSED, OPENING, OPEN, CLOSING;

    public String jsonName() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
