package eu.brain.iot.dashboard;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;

/**
 * What happened in the warehouse, from the bus's events and the doors' changes: the counters, and the log of the
 * last decisions (commands with their outcomes, one entry per command id).
 * <p>
 * Thread: owned by the dashboard's thread ({@link Hub}).
 */
final class Activity implements Devices.DoorWatcher {

    private static final int SEEN_COMMANDS = 4_096;
    private static final int STORAGE_AREA = 3;

    private final Map<String, Long> counters = new LinkedHashMap<>();
    private final LinkedHashMap<String, Map<String, Object>> decisions = new LinkedHashMap<>();
    private final LinkedHashSet<String> seen = new LinkedHashSet<>();
    private final LinkedHashSet<String> changedDecisions = new LinkedHashSet<>();
    private final int logSize;
    private boolean countersChanged;
    private long anonymous;

    Activity(int logSize) {
        this.logSize = logSize;
        for (String c : List.of("cartsDelivered", "cartsLifted", "doorOpenings", "robotInFront",
                "robotInFrontResolved", "doorInFront", "commandsSent", "commandsRefused", "missionsFinished",
                "missionsFailed", "unreachableEvents", "behavioursInstalled")) {
            counters.put(c, 0L);
        }
    }

    @Override
    public void doorState(String doorId, String before, String after) {
        if ("open".equals(after)) {
            count("doorOpenings");
        }
    }

    /** One bus event; {@code devices} tells where a robot stands (for carts delivered to storage). */
    void event(String type, Map<String, ?> f, Devices devices) {
        String simple = type.substring(type.lastIndexOf('.') + 1);
        switch (simple) {
            case "CommandOutcome" -> outcome(f);
            case "ObstacleDetected" -> count("ROBOT".equals(str(f, "kind")) ? "robotInFront" : "doorInFront");
            case "ObstacleCleared" -> {
                if ("ROBOT".equals(str(f, "kind"))) {
                    count("robotInFrontResolved");
                }
            }
            case "CartLifted" -> count("cartsLifted");
            case "CartPlaced" -> {
                Object area = devices.value(str(f, "robotId"), "position", "area");
                if (area instanceof Number n && n.intValue() == STORAGE_AREA) {
                    count("cartsDelivered");
                }
            }
            case "MissionFinished" -> count("missionsFinished");
            case "MissionFailed" -> count("missionsFailed");
            case "DeviceUnreachable" -> count("unreachableEvents");
            case "BehaviourInstalled" -> count("behavioursInstalled");
            default -> {
                if (simple.endsWith("Command")) {
                    command(simple, f);
                }
            }
        }
    }

    private void command(String command, Map<String, ?> f) {
        String id = commandId(f);
        Map<String, Object> d = decision(id);
        d.put("command", command);
        d.put("deviceId", str(f, "deviceId"));
        Map<String, Object> params = new LinkedHashMap<>();
        for (String p : List.of("x", "y", "missionType", "missionId")) {
            if (f.get(p) != null) {
                params.put(p, f.get(p));
            }
        }
        d.put("params", params);
        d.putIfAbsent("outcome", "sent");
        d.putIfAbsent("at", time(f));
    }

    private void outcome(Map<String, ?> f) {
        String id = commandId(f);
        Map<String, Object> d = decision(id);
        d.putIfAbsent("command", str(f, "command"));
        d.putIfAbsent("deviceId", str(f, "deviceId"));
        boolean accepted = Boolean.TRUE.equals(f.get("accepted"));
        d.put("outcome", accepted ? "accepted" : "refused");
        d.put("reason", str(f, "reason"));
        d.put("status", f.get("status"));
        d.put("missionId", f.get("missionId"));
        d.put("at", time(f));
        if (!accepted) {
            count("commandsRefused");
        }
    }

    /** The log entry of a command, made (and the command counted as sent) when it is seen first. */
    private Map<String, Object> decision(String id) {
        if (seen.add(id)) {
            count("commandsSent");
            if (seen.size() > SEEN_COMMANDS) {
                seen.remove(seen.iterator().next());
            }
        }
        Map<String, Object> d = decisions.remove(id); // re-inserted last: the log is in order of the last news
        if (d == null) {
            d = new LinkedHashMap<>();
            d.put("commandId", id);
        }
        decisions.put(id, d);
        while (decisions.size() > logSize) {
            decisions.remove(decisions.keySet().iterator().next());
        }
        changedDecisions.add(id);
        return d;
    }

    private String commandId(Map<String, ?> f) {
        String id = str(f, "commandId");
        return id != null ? id : "unnamed-" + (++anonymous);
    }

    private void count(String counter) {
        counters.merge(counter, 1L, Long::sum);
        countersChanged = true;
    }

    Map<String, Long> counters() {
        return new LinkedHashMap<>(counters);
    }

    /** The counters, if they changed since the last call, else {@code null}. */
    Map<String, Long> takeCounters() {
        if (!countersChanged) {
            return null;
        }
        countersChanged = false;
        return counters();
    }

    List<Map<String, Object>> decisions() {
        return new ArrayList<>(decisions.values());
    }

    /** Log entries new or changed since the last call (in log order), possibly empty. */
    List<Map<String, Object>> takeDecisions() {
        List<Map<String, Object>> out = new ArrayList<>();
        for (Map.Entry<String, Map<String, Object>> e : decisions.entrySet()) {
            if (changedDecisions.contains(e.getKey())) {
                out.add(new LinkedHashMap<>(e.getValue()));
            }
        }
        changedDecisions.clear();
        return out;
    }

    private static String str(Map<String, ?> f, String name) {
        Object v = f.get(name);
        return v == null ? null : v.toString();
    }

    private static Object time(Map<String, ?> f) {
        Object t = f.get("timestamp");
        return t == null ? System.currentTimeMillis() : t.toString();
    }
}
