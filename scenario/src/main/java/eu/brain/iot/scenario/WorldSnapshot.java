package eu.brain.iot.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * One {@code GET /world} document of robot-sim (map, robots, carts, doors, counters), read the way its README says:
 * the ground truth the scenario is judged on (here and in the multi-node tests in containers). Immutable.
 */
public record WorldSnapshot(JsonNode doc) {

    private static final int DOCKING = 1;

    /**
     * A robot commanded by another node than the one that commanded it before (robot-sim's {@code commandOrigins}):
     * {@code from}'s last command, then {@code to}'s, in warehouse time and wall time (epoch ms).
     */
    public record Handover(String robot, String from, String to, long fromWarehouseMs, long fromWallMillis,
                    long warehouseMs, long wallMillis) {
        long gapWallMillis() {
            return wallMillis - fromWallMillis;
        }

        static Handover of(JsonNode c) {
            return new Handover(c.path("robot").asText(), c.path("from").asText(), c.path("to").asText(),
                    c.path("fromLastWarehouseMs").asLong(), c.path("fromLastWallMillis").asLong(),
                    c.path("warehouseMs").asLong(), c.path("wallMillis").asLong());
        }
    }

    long step() {
        return doc.path("step").asLong();
    }

    JsonNode counters() {
        return doc.path("counters");
    }

    long stepMillis() {
        return counters().path("stepMillis").asLong(Options.STEP_MILLIS);
    }

    public long warehouseMillis() {
        return step() * stepMillis();
    }

    int robotCount() {
        return doc.path("robots").size();
    }

    int cartCount() {
        return doc.path("carts").size();
    }

    /** Carts standing (not carried) on a storage cell of the map: REQ-1 for that cart. */
    int cartsInStorage() {
        return cartCount() - cartsNotInStorage().size();
    }

    /** Each cart not delivered, with where it is: {@code cart2 at (10,7)} or {@code cart2 carried by robot1}. */
    List<String> cartsNotInStorage() {
        List<String> missing = new ArrayList<>();
        JsonNode rows = doc.path("map");
        for (JsonNode c : doc.path("carts")) {
            int x = c.path("x").asInt();
            int y = c.path("y").asInt();
            JsonNode by = c.path("carriedBy");
            String row = rows.path(y).asText("");
            boolean onStorage = x >= 0 && x < row.length() && row.charAt(x) == 's';
            if (!by.isNull() && !by.isMissingNode()) {
                missing.add(c.path("id").asText() + " carried by " + by.asText() + " at (" + x + "," + y + ")");
            } else if (!onStorage) {
                missing.add(c.path("id").asText() + " at (" + x + "," + y + ")");
            }
        }
        return missing;
    }

    /**
     * Each robot not back home, with why: a robot is home when it stands in the docking area, carries nothing and
     * has no mission running or queued.
     */
    List<String> robotsNotHome() {
        List<String> away = new ArrayList<>();
        for (JsonNode r : doc.path("robots")) {
            List<String> why = new ArrayList<>();
            if (r.path("area").asInt() != DOCKING) {
                why.add("at (" + r.path("x").asInt() + "," + r.path("y").asInt() + "), area " + r.path("area").asInt());
            }
            if (!r.path("cart").isNull() && !r.path("cart").isMissingNode()) {
                why.add("carrying " + r.path("cart").asText());
            }
            String mission = r.path("mission").path("state").asText("");
            if (mission.equals("running") || mission.equals("queued")) {
                why.add("mission " + r.path("mission").path("type").asText() + " " + mission);
            }
            if (!why.isEmpty()) {
                away.add(r.path("id").asText() + " " + String.join(", ", why));
            }
        }
        return away;
    }

    boolean allDelivered() {
        return cartsNotInStorage().isEmpty();
    }

    public boolean finished() {
        return allDelivered() && robotsNotHome().isEmpty();
    }

    long nearMisses() {
        return counters().path("nearMisses").asLong();
    }

    long deadlocks() {
        return counters().path("deadlocks").asLong();
    }

    long waitSteps() {
        return counters().path("waitSteps").asLong();
    }

    long longestWaitMs() {
        return counters().path("longestWaitMs").asLong();
    }

    long waitingNow() {
        return counters().path("waitingNow").asLong();
    }

    long waitsEnded() {
        return counters().path("waitsEnded").asLong();
    }

    long doorOpenings() {
        return counters().path("doorOpenings").asLong();
    }

    long commandsAccepted() {
        return counters().path("commands").path("accepted").asLong();
    }

    long commandsRefused() {
        return counters().path("commands").path("refused").asLong();
    }

    /** Missions that failed when their turn came (a precondition that no longer held, no path). */
    long missionsFailed() {
        return counters().path("missions").path("failed").asLong();
    }

    long missionsCancelled() {
        return counters().path("missions").path("cancelled").asLong();
    }

    /** Refused commands by HTTP status ("503": the robot was offline). */
    Map<String, Long> refusedByStatus() {
        Map<String, Long> by = new TreeMap<>();
        counters().path("commands").path("refusedByStatus").fields()
                .forEachRemaining(e -> by.put(e.getKey(), e.getValue().asLong()));
        return by;
    }

    /** Ended waits behind another robot: length in steps to how many. */
    TreeMap<Long, Long> endedWaits() {
        TreeMap<Long, Long> by = new TreeMap<>();
        counters().path("endedWaits").fields()
                .forEachRemaining(e -> by.put(Long.parseLong(e.getKey()), e.getValue().asLong()));
        return by;
    }

    /** Robots whose longest single wait behind another robot exceeded the limit: {@code robot2 waited 12.5 s}. */
    List<String> waitsOver(long limitMs) {
        List<String> over = new ArrayList<>();
        counters().path("perRobot").fields().forEachRemaining(e -> {
            long longest = e.getValue().path("longestWaitMs").asLong();
            if (longest > limitMs) {
                boolean now = e.getValue().path("waitingSteps").asLong() > 0;
                over.add(e.getKey() + " waited " + WarehouseTime.format(longest) + (now ? " (still waiting)" : ""));
            }
        });
        return over;
    }

    private JsonNode commandOrigins() {
        return doc.path("commandOrigins");
    }

    /** Per robot that took a command, the node that sent it the last one ({@code unknown}: it named none). */
    public Map<String, String> lastCommanders() {
        Map<String, String> by = new TreeMap<>();
        commandOrigins().path("robots").fields()
                .forEachRemaining(e -> by.put(e.getKey(), e.getValue().path("node").asText()));
        return by;
    }

    /**
     * Every hand-over robot-sim kept, oldest first: its bounded log, and per robot the closest one (kept whatever the
     * log dropped), each once.
     */
    public List<Handover> handovers() {
        Map<String, Handover> all = new LinkedHashMap<>();
        for (JsonNode c : commandOrigins().path("changes")) {
            Handover h = Handover.of(c);
            all.put(h.robot() + "@" + h.wallMillis() + ">" + h.to(), h);
        }
        commandOrigins().path("robots").fields().forEachRemaining(e -> {
            JsonNode closest = e.getValue().path("closestHandover");
            if (closest.isObject()) {
                Handover h = Handover.of(closest);
                all.putIfAbsent(h.robot() + "@" + h.wallMillis() + ">" + h.to(), h);
            }
        });
        List<Handover> sorted = new ArrayList<>(all.values());
        sorted.sort(Comparator.comparingLong(Handover::wallMillis));
        return sorted;
    }

    /** Hand-overs in all, per robot's count (the log may have dropped some). */
    long handoverCount() {
        long n = 0;
        for (JsonNode r : commandOrigins().path("robots")) {
            n += r.path("handovers").asLong();
        }
        return n;
    }
}
