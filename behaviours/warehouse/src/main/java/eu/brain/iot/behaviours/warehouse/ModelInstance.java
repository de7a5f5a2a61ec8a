package eu.brain.iot.behaviours.warehouse;

/**
 * Which copy of the system model an extern function call is for. A generated behaviour hosts one copy of Listing 4
 * per group and calls {@code bipInstance(group, component)} on its extern functions before the calls it makes for
 * one instance (bip/README, "Groups"); the extern functions keep that here and map the model's robot number back to
 * the fleet's robot with {@link RobotNames}: {@code moveTo(2, ...)} after {@code bipInstance("g4", "Robot2")} is
 * for robot11.
 * <p>
 * Threads: the generated behaviour calls {@code bipInstance} and then the functions on the same thread (its
 * methods are synchronized); the instance is kept per thread, so calls of two behaviours (or of one behaviour from
 * two threads) never see each other's instance.
 */
public final class ModelInstance {

    private final ThreadLocal<String> group = new ThreadLocal<>();

    /** Called from the extern functions' {@code bipInstance}. */
    public void set(String group, String component) {
        this.group.set(group == null ? "" : group);
    }

    /** @return the group of the instance the current call is for; "" (the default group) when none was named */
    public String group() {
        String g = group.get();
        return g == null ? "" : g;
    }

    /**
     * @param k the model's robot number (the atom's parameter: {@code Robot2} is {@code Robot_behavior(2)})
     * @return the fleet's robot of the current group (the default group is read as g1)
     */
    public String robotId(int k) {
        return RobotNames.robotId(group(), k);
    }
}
