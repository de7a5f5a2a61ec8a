package eu.brain.iot.scenario;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The behaviours' configuration for a run, by PID: the one place where the scenario sets what the robot, door and
 * orchestrator behaviours read from Config Admin (for example how long a robot waits before it asks the orchestrator
 * again, in warehouse time, which the speed factor turns into wall time). Each entry becomes
 * {@code <pid>.cfg} in the run's node configuration folder. Today the behaviours read no configuration, so the
 * table is empty; a user passes any other setting with {@code --node-config FILE}. Stateless.
 */
final class BehaviourSettings {
    private BehaviourSettings() {
    }

    /** PID to properties. */
    static Map<String, Map<String, Object>> forRun(Options o) {
        Map<String, Map<String, Object>> byPid = new LinkedHashMap<>();
        // The behaviours' PIDs and keys go here once they have configuration, e.g.
        // byPid.put("<robot behaviour PID>", Map.of("speed.factor", o.speed()));
        return byPid;
    }
}
