package eu.brain.iot.robotsim.world;

/** The robot_local_control components that take missions. */
public enum MissionType {
    GOTO("GoToComponent"), PICK("PickComponent"), PLACE("PlaceComponent");

    private final String component;

    MissionType(String component) {
        this.component = component;
    }

    /** The component name in the REST path, e.g. {@code GoToComponent}. */
    public String component() {
        return component;
    }

    /** The JSON name: goto, pick, place. */
    public String jsonName() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
