package eu.brain.iot.robotsim.fault;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * Faults injected into the answers for one robot (or the whole fleet). Rates are fractions 0..1 of requests,
 * applied deterministically (a rate of 0.25 hits every 4th request). Precedence when several apply to the same
 * request: offline, then drop, then HTTP 500, then malformed JSON; latency delays every answer (and every drop).
 *
 * @param latencyMs     added delay before answering, 0..60000 ms
 * @param errorRate     fraction of requests answered 500 without acting on them
 * @param malformedRate fraction of requests answered 200 with a truncated, unparseable JSON body
 * @param dropRate      fraction of requests whose connection is closed without an answer (nothing done)
 * @param offline       the robot answers 503 to everything and stands still in the warehouse
 */
@JsonPropertyOrder({"latencyMs", "errorRate", "malformedRate", "dropRate", "offline"})
public record FaultSettings(int latencyMs, double errorRate, double malformedRate, double dropRate, boolean offline) {
    public static final FaultSettings NONE = new FaultSettings(0, 0, 0, 0, false);
    public static final List<String> FIELDS = List.of("latencyMs", "errorRate", "malformedRate", "dropRate", "offline");

    public boolean any() {
        return !equals(NONE);
    }

    /**
     * A copy with one field changed; {@code value} is a Number, Boolean or String (from a flag).
     *
     * @throws FaultFieldException naming the field when the name or value is not acceptable
     */
    public FaultSettings with(String field, Object value) throws FaultFieldException {
        return switch (field) {
            case "latencyMs" -> new FaultSettings(latency(value), errorRate, malformedRate, dropRate, offline);
            case "errorRate" -> new FaultSettings(latencyMs, rate(field, value), malformedRate, dropRate, offline);
            case "malformedRate" -> new FaultSettings(latencyMs, errorRate, rate(field, value), dropRate, offline);
            case "dropRate" -> new FaultSettings(latencyMs, errorRate, malformedRate, rate(field, value), offline);
            case "offline" -> new FaultSettings(latencyMs, errorRate, malformedRate, dropRate, bool(value));
            default -> throw new FaultFieldException(field, "unknown fault '" + field + "' (known: "
                    + String.join(", ", FIELDS) + ")");
        };
    }

    private static int latency(Object value) throws FaultFieldException {
        Number n = number("latencyMs", value);
        if (n == null || n.doubleValue() != Math.rint(n.doubleValue()) || n.doubleValue() < 0
                || n.doubleValue() > 60_000) {
            throw new FaultFieldException("latencyMs", "latencyMs must be a whole number of milliseconds 0..60000");
        }
        return n.intValue();
    }

    private static double rate(String field, Object value) throws FaultFieldException {
        Number n = number(field, value);
        if (n == null || !(n.doubleValue() >= 0 && n.doubleValue() <= 1)) {
            throw new FaultFieldException(field, field + " must be a number from 0 to 1");
        }
        return n.doubleValue();
    }

    private static Number number(String field, Object value) throws FaultFieldException {
        if (value instanceof Number n) {
            return n;
        }
        if (value instanceof String s) {
            try {
                return Double.parseDouble(s.strip());
            } catch (NumberFormatException e) {
                throw new FaultFieldException(field, field + " must be a number, found '" + s + "'");
            }
        }
        return null;
    }

    private static boolean bool(Object value) throws FaultFieldException {
        if (value instanceof Boolean b) {
            return b;
        }
        if (value instanceof String s && (s.equals("true") || s.equals("false"))) {
            return Boolean.parseBoolean(s);
        }
        throw new FaultFieldException("offline", "offline must be true or false");
    }
}
