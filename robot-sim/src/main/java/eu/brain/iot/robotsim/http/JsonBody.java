package eu.brain.iot.robotsim.http;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import eu.brain.iot.robotsim.view.Json;
import java.util.Iterator;
import java.util.Set;

/**
 * Reads small JSON request bodies strictly: a wrong type, an unknown or repeated field is a 400 that names the field.
 */
final class JsonBody {
    /** Bodies are flat objects; a little room for a nested value that is then refused by type. */
    static final int MAX_DEPTH = 16;

    private final ObjectNode node;

    private JsonBody(ObjectNode node) {
        this.node = node;
    }

    /**
     * Parses a body that must be a JSON object; an empty body counts as {@code {}}. Fields outside
     * {@code allowed} are refused, and so are a key given twice and nesting deeper than {@link #MAX_DEPTH}.
     */
    static JsonBody parse(byte[] body, Set<String> allowed) throws ApiException {
        ObjectNode object;
        if (body.length == 0 || ServerExchange.utf8(body).isBlank()) {
            object = Json.MAPPER.createObjectNode();
        } else {
            JsonNode tree = StrictJsonReader.read(body, MAX_DEPTH);
            if (!tree.isObject()) {
                throw new ApiException(400, "body", "the body must be a JSON object");
            }
            object = (ObjectNode) tree;
        }
        for (Iterator<String> names = object.fieldNames(); names.hasNext(); ) {
            String name = names.next();
            if (!allowed.contains(name)) {
                throw new ApiException(400, name, "unknown field '" + name + "'"
                        + (allowed.isEmpty() ? " (this request takes no fields)" : " (expected: "
                        + String.join(", ", allowed.stream().sorted().toList()) + ")"));
            }
        }
        return new JsonBody(object);
    }

    ObjectNode node() {
        return node;
    }

    boolean has(String field) {
        return node.has(field);
    }

    /** A required whole number (1 and 1.0 are fine; 1.5, "1" and null are not). */
    int requireInt(String field) throws ApiException {
        JsonNode v = node.get(field);
        if (v == null) {
            throw new ApiException(400, field, "missing field '" + field + "' (a whole number)");
        }
        return intValue(field, v);
    }

    /** An optional whole number, null when absent. */
    Long optionalLong(String field) throws ApiException {
        JsonNode v = node.get(field);
        if (v == null) {
            return null;
        }
        if (!v.isNumber() || v.asDouble() != Math.rint(v.asDouble())) {
            throw new ApiException(400, field, "field '" + field + "' must be a whole number, found " + v);
        }
        return v.asLong();
    }

    /** A required number. */
    double requireNumber(String field) throws ApiException {
        JsonNode v = node.get(field);
        if (v == null) {
            throw new ApiException(400, field, "missing field '" + field + "' (a number)");
        }
        if (!v.isNumber()) {
            throw new ApiException(400, field, "field '" + field + "' must be a number, found " + v);
        }
        return v.asDouble();
    }

    private static int intValue(String field, JsonNode v) throws ApiException {
        if (!v.isNumber() || v.asDouble() != Math.rint(v.asDouble())
                || v.asDouble() < Integer.MIN_VALUE || v.asDouble() > Integer.MAX_VALUE) {
            throw new ApiException(400, field, "field '" + field + "' must be a whole number, found " + v);
        }
        return v.asInt();
    }
}
