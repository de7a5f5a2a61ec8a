package eu.brain.iot.behaviours.warehouse;

/**
 * How the fleet's robots map to the components of the system model (Listing 4: {@code Robot1..3}): robot-sim's
 * {@code robotK} is component {@code Robot<(K-1)%3+1>} of group {@code g<ceil(K/3)>}: each generated behaviour hosts one
 * copy of the compound per group (bip/README, "Groups"), so 30 robots are 10 groups. The default group (null or "")
 * is read as g1 by {@link #robotId}; the bindings never publish to it, so it stays idle. A group whose last robots
 * do not exist (robot31 alone in g11) keeps their instances in START: the orchestrator's subset rendezvous never
 * waits for them.
 */
public final class RobotNames {

    /** Robots per compound (Listing 4). */
    public static final int PER_GROUP = 3;

    private RobotNames() {
    }

    /** @return K of {@code robotK}, or -1 when the id is not of that form */
    public static int number(String robotId) {
        if (robotId == null || !robotId.startsWith("robot")) {
            return -1;
        }
        try {
            int k = Integer.parseInt(robotId.substring(5));
            return k > 0 ? k : -1;
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    /** @return the component name, e.g. {@code Robot2} for {@code robot5} */
    public static String component(int k) {
        return "Robot" + ((k - 1) % PER_GROUP + 1);
    }

    /** @return the group, e.g. {@code g2} for {@code robot5} */
    public static String group(int k) {
        return "g" + ((k + PER_GROUP - 1) / PER_GROUP);
    }

    /** @return the fleet's robot id of a component of a group ({@code g2}, {@code Robot2}: {@code robot5}) */
    public static String robotId(String group, int componentIndex) {
        return "robot" + ((groupNumber(group) - 1) * PER_GROUP + componentIndex);
    }

    /** @return the fleet's robot id of a component ({@code g2}, {@code Robot2}: {@code robot5}) */
    public static String robotId(String group, String component) {
        return robotId(group, Integer.parseInt(component.substring("Robot".length())));
    }

    /** @return N of group {@code gN}; 1 for the default group (null or "") */
    static int groupNumber(String group) {
        if (group == null || group.isEmpty()) {
            return 1;
        }
        if (!group.startsWith("g")) {
            throw new IllegalArgumentException("group \"" + group + "\" is not of the form gN (N >= 1)");
        }
        int n = Integer.parseInt(group.substring(1));
        if (n < 1) {
            throw new IllegalArgumentException("group \"" + group + "\" is not of the form gN (N >= 1)");
        }
        return n;
    }

    /** @return whether robot {@code robotId} belongs to {@code group} (the default group is g1) */
    public static boolean inGroup(String robotId, String group) {
        int k = number(robotId);
        return k > 0 && (k + PER_GROUP - 1) / PER_GROUP == groupNumber(group);
    }
}
