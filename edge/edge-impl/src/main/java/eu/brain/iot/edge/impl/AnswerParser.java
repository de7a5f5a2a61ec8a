package eu.brain.iot.edge.impl;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Reads the fleet's JSON answers, strictly enough to trust them: a missing field, a wrong type or an unknown
 * state is an error that names the device and the field; unknown extra fields are ignored (a newer fleet may
 * add some). Thread-safe (Jackson's mapper is), so it runs on the HTTP threads.
 */
final class AnswerParser {

    private static final Set<String> ROBOT_STATES = Set.of("running", "stopped");
    private static final Set<String> HEADINGS = Set.of("N", "E", "S", "W");
    private static final Set<String> DOOR_STATES = Set.of("closed", "opening", "open", "closing");
    private static final Set<String> MISSION_TYPES = Set.of("goto", "pick", "place");
    private static final Set<String> MISSION_STATES = Set.of("queued", "running", "finished", "failed");

    private final ObjectMapper mapper = new ObjectMapper();

    /** @throws DeviceIOException saying what is wrong with the answer */
    RobotAnswer robot(String robotId, byte[] body) throws DeviceIOException {
        Fields f = new Fields(robotId, tree(robotId, body));
        String id = f.text("id");
        if (!robotId.equals(id)) {
            throw new DeviceIOException("answer of " + robotId + " is about '" + id + "'");
        }
        JsonNode m = f.node.get("mission");
        RobotAnswer.Mission mission = null;
        if (m != null && !m.isNull()) {
            Fields mf = new Fields(robotId + " mission", m);
            JsonNode goal = m.get("goal");
            Integer gx = null;
            Integer gy = null;
            if (goal != null && !goal.isNull()) {
                Fields gf = new Fields(robotId + " mission goal", goal);
                gx = gf.integer("x");
                gy = gf.integer("y");
            }
            mission = new RobotAnswer.Mission(mf.longValue("id"), mf.oneOf("type", MISSION_TYPES),
                    mf.oneOf("state", MISSION_STATES), mf.optionalText("reason"), gx, gy);
        }
        int detect = f.integer("detect");
        if (detect < 0 || detect > 2) {
            throw new DeviceIOException("answer of " + robotId + ": 'detect' must be 0, 1 or 2, found " + detect);
        }
        return new RobotAnswer(id, f.integer("x"), f.integer("y"), f.oneOf("heading", HEADINGS), f.integer("area"),
                f.oneOf("state", ROBOT_STATES), detect, f.optionalText("cart"), mission, f.optionalInt("nearMisses"),
                f.optionalInt("deadlocks"));
    }

    /** @throws DeviceIOException saying what is wrong with the answer */
    DoorAnswer door(String doorId, byte[] body) throws DeviceIOException {
        Fields f = new Fields(doorId, tree(doorId, body));
        String id = f.text("id");
        if (!doorId.equals(id)) {
            throw new DeviceIOException("answer of " + doorId + " is about '" + id + "'");
        }
        JsonNode data = f.node.get("data");
        if (data == null || !data.isNumber()) {
            throw new DeviceIOException("answer of " + doorId + ": 'data' must be a number");
        }
        return new DoorAnswer(id, f.integer("x"), f.integer("y"), f.oneOf("state", DOOR_STATES), data.asDouble(),
                f.optionalInt("stepsLeft"));
    }

    /** The fleet's inventory ({@code GET /}): robot and door ids. */
    Inventory inventory(byte[] body) throws DeviceIOException {
        JsonNode root = tree("the fleet", body);
        return new Inventory(ids(root, "robots"), ids(root, "doors"));
    }

    record Inventory(List<String> robots, List<String> doors) {
    }

    /** The fleet's world ({@code GET /world}): its map and carts (robots and doors are polled on their own). */
    WorldAnswer world(byte[] body) throws DeviceIOException {
        Fields f = new Fields("the fleet's world", tree("the fleet's world", body));
        JsonNode rows = f.node.get("map");
        if (rows == null || !rows.isArray()) {
            throw new DeviceIOException("answer of the fleet's world: 'map' must be a list of rows");
        }
        StringBuilder grid = new StringBuilder();
        for (JsonNode row : rows) {
            grid.append(grid.length() == 0 ? "" : "\n").append(row.asText());
        }
        String name = f.optionalText("name");
        WorldAnswer.Map map = new WorldAnswer.Map(WorldAnswer.WAREHOUSE, name == null ? "" : name, f.integer("width"),
                f.integer("height"), grid.toString());
        JsonNode carts = f.node.get("carts");
        if (carts == null || !carts.isArray()) {
            throw new DeviceIOException("answer of the fleet's world: 'carts' must be a list");
        }
        List<WorldAnswer.Cart> list = new ArrayList<>();
        for (JsonNode c : carts) {
            Fields cf = new Fields("the fleet's world, a cart", c);
            list.add(new WorldAnswer.Cart(cf.text("id"), cf.integer("x"), cf.integer("y"), cf.optionalText("carriedBy")));
        }
        return new WorldAnswer(map, list);
    }

    /** The id of the mission in a command's answer ({@code {"mission":{"id":N,...}}}), or {@code null}. */
    Long missionId(byte[] body) {
        try {
            JsonNode id = mapper.readTree(body).path("mission").path("id");
            return id.isIntegralNumber() ? id.asLong() : null;
        } catch (IOException e) {
            return null;
        }
    }

    /** The history of a component ({@code query_state}): missions that ended, oldest first. */
    List<RobotAnswer.Mission> history(String robotId, byte[] body) throws DeviceIOException {
        JsonNode history = tree(robotId, body).path("history");
        List<RobotAnswer.Mission> ended = new ArrayList<>();
        for (JsonNode m : history) {
            Fields mf = new Fields(robotId + " history", m);
            JsonNode goal = m.get("goal");
            Integer gx = goal != null && goal.isObject() ? goal.path("x").asInt() : null;
            Integer gy = goal != null && goal.isObject() ? goal.path("y").asInt() : null;
            ended.add(new RobotAnswer.Mission(mf.longValue("id"), mf.oneOf("type", MISSION_TYPES),
                    mf.oneOf("state", MISSION_STATES), mf.optionalText("reason"), gx, gy));
        }
        return ended;
    }

    /** The {@code error} text of a fleet error answer, else the start of the body. */
    String errorText(HttpAnswer answer) {
        try {
            JsonNode error = mapper.readTree(answer.body()).get("error");
            if (error != null && error.isTextual()) {
                return error.asText();
            }
        } catch (IOException e) {
            // not JSON: show what came
        }
        String text = new String(answer.body(), java.nio.charset.StandardCharsets.UTF_8).strip();
        return text.isEmpty() ? "(no body)" : text.length() > 200 ? text.substring(0, 200) + "..." : text;
    }

    private JsonNode tree(String who, byte[] body) throws DeviceIOException {
        JsonNode node;
        try {
            node = mapper.readTree(body);
        } catch (JsonProcessingException e) {
            JsonLocation at = e.getLocation();
            String where = at == null ? "" : " at line " + at.getLineNr() + ", column " + at.getColumnNr();
            throw new DeviceIOException("malformed JSON from " + who + where + ": " + e.getOriginalMessage());
        } catch (IOException e) {
            throw new DeviceIOException("unreadable answer from " + who + ": " + e.getMessage());
        }
        if (node == null || !node.isObject()) {
            throw new DeviceIOException("answer of " + who + " is not a JSON object");
        }
        return node;
    }

    private static List<String> ids(JsonNode root, String field) throws DeviceIOException {
        JsonNode array = root.get(field);
        if (array == null || !array.isArray()) {
            throw new DeviceIOException("the fleet's inventory has no '" + field + "' list");
        }
        List<String> ids = new ArrayList<>();
        for (JsonNode id : array) {
            ids.add(id.asText());
        }
        return ids;
    }

    /** Field access that says which field of which device is wrong. */
    private record Fields(String who, JsonNode node) {

        String text(String name) throws DeviceIOException {
            JsonNode v = node.get(name);
            if (v == null || !v.isTextual()) {
                throw wrong(name, "a string");
            }
            return v.asText();
        }

        String optionalText(String name) throws DeviceIOException {
            JsonNode v = node.get(name);
            if (v == null || v.isNull()) {
                return null;
            }
            if (!v.isTextual()) {
                throw wrong(name, "a string or null");
            }
            return v.asText();
        }

        String oneOf(String name, Set<String> allowed) throws DeviceIOException {
            String v = text(name);
            if (!allowed.contains(v)) {
                throw new DeviceIOException("answer of " + who + ": '" + name + "' is '" + v + "', expected one of "
                        + new java.util.TreeSet<>(allowed));
            }
            return v;
        }

        int integer(String name) throws DeviceIOException {
            JsonNode v = node.get(name);
            if (v == null || !v.canConvertToInt() || !v.isIntegralNumber()) {
                throw wrong(name, "a whole number");
            }
            return v.asInt();
        }

        int optionalInt(String name) throws DeviceIOException {
            return node.has(name) ? integer(name) : 0;
        }

        long longValue(String name) throws DeviceIOException {
            JsonNode v = node.get(name);
            if (v == null || !v.isIntegralNumber()) {
                throw wrong(name, "a whole number");
            }
            return v.asLong();
        }

        private DeviceIOException wrong(String name, String expected) {
            JsonNode v = node.get(name);
            return new DeviceIOException("answer of " + who + ": '" + name + "' must be " + expected + ", found "
                    + (v == null ? "nothing" : v.toString()));
        }
    }
}
