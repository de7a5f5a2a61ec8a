package eu.brain.iot.edge.impl;

import java.util.List;
import java.util.Map;

import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CloseDoorCommand;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;
import eu.brain.iot.edge.model.api.UnknownResourceException;

/** Turns an action of the model (sensiNact's ACT on an action resource) into the command event it stands for. */
final class Actions {

    static final String SERVICE = "control";
    /** The parameters each action takes (kind:action); an action not listed takes none. */
    private static final Map<String, List<String>> PARAMETERS = Map.of("ROBOT:goTo", List.of("x", "y"),
            "ROBOT:cancel", List.of("missionType", "missionId"));

    private Actions() {
    }

    /**
     * @throws UnknownResourceException when the kind of provider has no such action
     * @throws IllegalArgumentException when a parameter is missing, of the wrong type or unknown (a typo must not
     *                                  run a different command than meant)
     */
    static EdgeCommand command(String providerId, DeviceKind kind, String service, String action,
            Map<String, Object> params) {
        if (!SERVICE.equals(service)) {
            throw new UnknownResourceException(providerId + " has no actions in service '" + service
                    + "' (actions: " + kind.actions + ")");
        }
        EdgeCommand command = switch (kind + ":" + action) {
            case "ROBOT:goTo" -> {
                GoToCommand g = new GoToCommand();
                g.x = whole(params, "x");
                g.y = whole(params, "y");
                yield g;
            }
            case "ROBOT:pick" -> new PickCartCommand();
            case "ROBOT:place" -> new PlaceCartCommand();
            case "ROBOT:cancel" -> {
                CancelMissionCommand c = new CancelMissionCommand();
                Object type = params.get("missionType");
                if (type != null && !(type instanceof String)) {
                    throw new IllegalArgumentException("parameter 'missionType' must be a string: goto, pick or place");
                }
                c.missionType = (String) type;
                c.missionId = params.get("missionId") == null ? null : (long) whole(params, "missionId");
                yield c;
            }
            case "DOOR:open" -> new OpenDoorCommand();
            case "DOOR:close" -> new CloseDoorCommand();
            default -> throw new UnknownResourceException(providerId + " has no action '" + action
                    + "' (actions: " + kind.actions + ")");
        };
        List<String> allowed = PARAMETERS.getOrDefault(kind + ":" + action, List.of());
        for (String name : new java.util.TreeSet<>(params.keySet())) {
            if (!allowed.contains(name)) {
                throw new IllegalArgumentException("unknown parameter '" + name + "': " + action
                        + (allowed.isEmpty() ? " takes no parameters" : " takes " + allowed));
            }
        }
        command.deviceId = providerId;
        return command;
    }

    private static int whole(Map<String, Object> params, String name) {
        Object v = params.get(name);
        if (v == null) {
            throw new IllegalArgumentException("parameter '" + name + "' is missing");
        }
        if (v instanceof Number n && n.doubleValue() == Math.rint(n.doubleValue())
                && Math.abs(n.doubleValue()) <= Integer.MAX_VALUE) {
            return n.intValue();
        }
        throw new IllegalArgumentException("parameter '" + name + "' must be a whole number, found " + v
                + (v instanceof String ? " (a string)" : ""));
    }
}
