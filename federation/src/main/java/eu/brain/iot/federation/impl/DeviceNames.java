package eu.brain.iot.federation.impl;

import java.util.List;
import java.util.Map;
import java.util.TreeSet;

/**
 * Which devices of the fleet an event names, for the choice of the node that installs a behaviour for it
 * ({@link InstallChoice}): the text values of its top-level fields {@link #FIELDS}, as the edge's events and commands
 * name a robot or a door ({@code robotId}, {@code doorId}, {@code deviceId}), sorted.
 * Other fields (a cart, a command's id) name no device that a node owns.
 * <p>
 * Stateless.
 */
final class DeviceNames {

    /** The fields that name a device of the fleet. */
    static final List<String> FIELDS = List.of("robotId", "doorId", "deviceId");

    private DeviceNames() {
    }

    /** @return the ids of the devices the event names, sorted, none twice; empty for {@code null} */
    static List<String> of(Map<String, ?> event) {
        if (event == null) {
            return List.of();
        }
        TreeSet<String> ids = new TreeSet<>();
        for (String field : FIELDS) {
            if (event.get(field) instanceof String id && !id.isBlank()) {
                ids.add(id);
            }
        }
        return List.copyOf(ids);
    }
}
