package eu.brain.iot.edge.impl;

import java.net.URI;
import java.util.List;
import java.util.Map;

/**
 * The kinds of provider: the two kinds of device of the fleet (where each answers, and the actions its provider
 * offers), and the carts and map the edge reads from the fleet's world.
 */
enum DeviceKind {
    ROBOT("robot", "robot_local_control/state",
            Map.of("control", List.of("goTo(x,y)", "pick", "place", "cancel(missionType?,missionId?)"))),
    DOOR("door", "door_controller/state", Map.of("control", List.of("open", "close"))),
    /** A cart of the world ({@code GET /world}), read by the {@link WorldReader}, not polled on its own. */
    CART("cart", null, Map.of()),
    /** The warehouse's map ({@code GET /world}), one provider {@code warehouse}, read by the {@link WorldReader}. */
    WAREHOUSE("warehouse", null, Map.of());

    final String label;
    private final String statePath;
    final Map<String, List<String>> actions;

    DeviceKind(String label, String statePath, Map<String, List<String>> actions) {
        this.label = label;
        this.statePath = statePath;
        this.actions = actions;
    }

    URI stateUri(URI base, String id) {
        return base.resolve(id + "/" + statePath);
    }
}
