package eu.brain.iot.scenario;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The behaviours' configuration for a run, by PID: the one place where the scenario sets what the robot, door and
 * orchestrator behaviours read from Config Admin. Their times are warehouse time; {@code speed} tells them how much
 * faster than wall time the warehouse runs, so that they look at the robots once per (scaled) poll and their patience
 * lasts as long in warehouse time as at real speed. Each entry becomes {@code <pid>.cfg} in the run's node
 * configuration folder; a user passes any other setting with {@code --node-config FILE}. A PID no behaviour reads is
 * harmless (Config Admin keeps it). Stateless.
 */
final class BehaviourSettings {
    static final String ROBOT_PID = "eu.brain.iot.behaviours.robot";
    static final String DOOR_PID = "eu.brain.iot.behaviours.door";

    private BehaviourSettings() {
    }

    /** PID to properties. */
    static Map<String, Map<String, Object>> forRun(Options o) {
        Map<String, Map<String, Object>> byPid = new LinkedHashMap<>();
        byPid.put(ROBOT_PID, Map.of("speed", o.speed(), "traffic", o.traffic())); // the bundle's own default: false
        byPid.put(DOOR_PID, Map.of("speed", o.speed()));
        return byPid;
    }
}
