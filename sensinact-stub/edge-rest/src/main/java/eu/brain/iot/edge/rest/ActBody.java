package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.io.InputStream;
import java.util.Map;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.type.TypeReference;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * An ACT request's body: a JSON object of the action's parameters ({@code {"x":9,"y":7}}), or nothing for an action
 * without parameters. Strict, so that a typo is an error rather than a silently different command: duplicate
 * keys and anything after the object are refused, and a syntax error names its line and column.
 */
final class ActBody {

    private static final ObjectMapper STRICT = new ObjectMapper()
            .enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS);
    private static final TypeReference<Map<String, Object>> MAP = new TypeReference<>() {
    };

    private ActBody() {
    }

    /**
     * @throws HttpError 400 for a body that is not a JSON object, 413 for one larger than {@code maxBytes}
     * @throws IOException when the request cannot be read
     */
    static Map<String, Object> parameters(InputStream in, int maxBytes, String example) throws IOException {
        byte[] bytes = in.readNBytes(maxBytes + 1);
        if (bytes.length > maxBytes) {
            throw new HttpError(413, "the body is larger than " + maxBytes + " bytes (act.max.body.bytes); an ACT "
                    + "takes a small JSON object of parameters such as " + example);
        }
        if (new String(bytes, java.nio.charset.StandardCharsets.UTF_8).isBlank()) {
            return Map.of();
        }
        JsonNode tree;
        try {
            tree = STRICT.readTree(bytes);
        } catch (JsonProcessingException e) {
            JsonLocation at = e.getLocation();
            String where = at == null ? "" : " at line " + at.getLineNr() + ", column " + at.getColumnNr();
            throw HttpError.badRequest("malformed JSON" + where + ": " + e.getOriginalMessage()
                    + "; send a JSON object of parameters such as " + example);
        }
        if (!tree.isObject()) {
            throw HttpError.badRequest("the body must be a JSON object of parameters such as " + example
                    + ", found a JSON " + tree.getNodeType().name().toLowerCase());
        }
        return STRICT.convertValue(tree, MAP);
    }
}
