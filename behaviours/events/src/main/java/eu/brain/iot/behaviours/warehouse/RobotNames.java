package eu.brain.iot.behaviours.warehouse;

/**
 * How the fleet's robots map to the components of the system model (Listing 4: {@code Robot1..3}): robot-sim's
 * {@code robotK} is component {@code Robot<(K-1)%3+1>} of group {@code g<ceil(K/3)>}. Until the behaviours host one
 * compound per group, only group {@code g1} (robot1..3) has components; the others are not driven (and say so).
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
        int g = group == null || group.isEmpty() ? 1 : Integer.parseInt(group.substring(1));
        return "robot" + ((g - 1) * PER_GROUP + componentIndex);
    }
}
