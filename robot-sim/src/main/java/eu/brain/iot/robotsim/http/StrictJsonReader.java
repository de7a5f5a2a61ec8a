package eu.brain.iot.robotsim.http;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import eu.brain.iot.robotsim.view.Json;
import java.io.IOException;

/**
 * Builds a JSON tree from a request body with Jackson's streaming parser, refusing what Jackson's own tree reader
 * lets through or reports badly: a key given twice in one object (Jackson keeps the last), nesting deeper than a
 * bound (checked before descending, so no deep recursion; Jackson's own limit reports no location) and anything after
 * the document. Every refusal is a 400 {@link ApiException} that says what and where. Stateless.
 */
final class StrictJsonReader {
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private StrictJsonReader() {
    }

    static JsonNode read(byte[] body, int maxDepth) throws ApiException {
        try (JsonParser p = Json.MAPPER.getFactory().createParser(body)) {
            JsonToken first = p.nextToken();
            if (first == null) {
                throw new ApiException(400, "body", "the body must be a JSON object");
            }
            JsonNode tree = value(p, first, 1, maxDepth);
            JsonToken after = p.nextToken();
            if (after != null) {
                throw new ApiException(400, "body", "unexpected '" + p.getText() + "' after the JSON document"
                        + at(p.currentTokenLocation()) + " (send one JSON object)");
            }
            return tree;
        } catch (StreamConstraintsException e) {
            throw new ApiException(400, "body", "malformed JSON: " + e.getOriginalMessage());
        } catch (JsonProcessingException e) {
            throw new ApiException(400, "body", "malformed JSON" + at(e.getLocation()) + ": " + e.getOriginalMessage());
        } catch (IOException e) {
            throw new ApiException(400, "body", "unreadable body: " + e.getMessage());
        }
    }

    private static JsonNode value(JsonParser p, JsonToken token, int depth, int maxDepth)
            throws IOException, ApiException {
        switch (token) {
            case START_OBJECT -> {
                checkDepth(p, depth, maxDepth);
                ObjectNode object = NODES.objectNode();
                for (JsonToken t = p.nextToken(); t != JsonToken.END_OBJECT; t = p.nextToken()) {
                    String name = p.currentName();
                    JsonLocation where = p.currentTokenLocation();
                    JsonNode v = value(p, p.nextToken(), depth + 1, maxDepth);
                    if (object.has(name)) {
                        throw new ApiException(400, name, "field '" + name + "' given twice" + at(where)
                                + " (give each field once)");
                    }
                    object.set(name, v);
                }
                return object;
            }
            case START_ARRAY -> {
                checkDepth(p, depth, maxDepth);
                ArrayNode array = NODES.arrayNode();
                for (JsonToken t = p.nextToken(); t != JsonToken.END_ARRAY; t = p.nextToken()) {
                    array.add(value(p, t, depth + 1, maxDepth));
                }
                return array;
            }
            case VALUE_STRING -> {
                return NODES.textNode(p.getText());
            }
            case VALUE_NUMBER_INT -> {
                return switch (p.getNumberType()) {
                    case INT -> NODES.numberNode(p.getIntValue());
                    case LONG -> NODES.numberNode(p.getLongValue());
                    default -> NODES.numberNode(p.getBigIntegerValue());
                };
            }
            case VALUE_NUMBER_FLOAT -> {
                return NODES.numberNode(p.getDoubleValue());
            }
            case VALUE_TRUE, VALUE_FALSE -> {
                return NODES.booleanNode(token == JsonToken.VALUE_TRUE);
            }
            case VALUE_NULL -> {
                return NODES.nullNode();
            }
            default -> throw new ApiException(400, "body", "malformed JSON" + at(p.currentTokenLocation())
                    + ": unexpected " + token);
        }
    }

    private static void checkDepth(JsonParser p, int depth, int maxDepth) throws ApiException {
        if (depth > maxDepth) {
            throw new ApiException(400, "body", "JSON nesting depth exceeds " + maxDepth + at(p.currentTokenLocation())
                    + " (robot-sim's request bodies are flat JSON objects)");
        }
    }

    private static String at(JsonLocation where) {
        return where == null ? "" : " at line " + where.getLineNr() + ", column " + where.getColumnNr();
    }
}
