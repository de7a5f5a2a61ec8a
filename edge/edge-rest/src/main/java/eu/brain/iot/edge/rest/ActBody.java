package eu.brain.iot.edge.rest;

import java.nio.charset.StandardCharsets;
import java.util.Map;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;
import com.fasterxml.jackson.core.type.TypeReference;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * An ACT request's body: a JSON object of the action's parameters ({@code {"x":9,"y":7}}), or nothing for an action
 * without parameters. Strict, so that a typo is an error rather than a silently different command: duplicate
 * keys, nesting deeper than {@value #MAX_DEPTH} and anything after the object are refused, and a syntax error names
 * its line and column. Which parameters an action takes is the device model's business (it names the unknown ones).
 */
final class ActBody {

    /** No action takes nested parameters: a few levels are room enough, and a deep document costs the parser. */
    static final int MAX_DEPTH = 16;
    private static final ObjectMapper STRICT = new ObjectMapper(JsonFactory.builder()
            .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(MAX_DEPTH).build()).build())
            .enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS);
    private static final TypeReference<Map<String, Object>> MAP = new TypeReference<>() {
    };

    private ActBody() {
    }

    /** @throws HttpError 400 for a body that is not a JSON object (the field is {@code body}) */
    static Map<String, Object> parameters(byte[] bytes, String example) {
        if (new String(bytes, StandardCharsets.UTF_8).isBlank()) {
            return Map.of();
        }
        JsonNode tree;
        try {
            tree = STRICT.readTree(bytes);
        } catch (StreamConstraintsException e) {
            throw HttpError.about(400, "body", "JSON nesting depth exceeds " + MAX_DEPTH + where(e.getLocation())
                    + "; an ACT takes a flat JSON object of parameters such as " + example);
        } catch (JsonProcessingException e) {
            throw HttpError.about(400, "body", "malformed JSON" + where(e.getLocation()) + ": "
                    + e.getOriginalMessage() + "; send a JSON object of parameters such as " + example);
        } catch (java.io.IOException e) {
            throw new IllegalStateException("reading bytes in memory cannot fail", e);
        }
        if (!tree.isObject()) {
            throw HttpError.about(400, "body", "the body must be a JSON object of parameters such as " + example
                    + ", found a JSON " + tree.getNodeType().name().toLowerCase());
        }
        return STRICT.convertValue(tree, MAP);
    }

    private static String where(JsonLocation at) {
        return at == null ? "" : " at line " + at.getLineNr() + ", column " + at.getColumnNr();
    }
}
