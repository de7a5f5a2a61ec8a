package eu.brain.iot.robotsim.http;

import java.util.regex.Pattern;

/**
 * The request header by which a fabric node names itself on the commands it sends ({@code X-Brain-Node: node2}):
 * a node name is 1 to 64 letters, digits, '_', '.' or '-'. A command without it is recorded as from
 * {@value #UNKNOWN}; one with another value is refused (400).
 */
final class CommanderHeader {
    static final String NAME = "X-Brain-Node";
    static final String UNKNOWN = "unknown";
    private static final Pattern NODE = Pattern.compile("[A-Za-z0-9_.-]{1,64}");

    private CommanderHeader() {
    }

    /**
     * @param value the header's value, or null when the request had none
     * @return the node's name
     * @throws ApiException 400 when the value is no node name
     */
    static String node(String value) throws ApiException {
        if (value == null) {
            return UNKNOWN;
        }
        String v = value.strip();
        if (!NODE.matcher(v).matches()) {
            String shown = v.length() > 64 ? v.substring(0, 64) + "..." : v;
            throw new ApiException(400, NAME, "header " + NAME + " must name the commanding node with 1 to 64 "
                    + "letters, digits, '_', '.' or '-' (e.g. " + NAME + ": node2), found '" + shown + "'");
        }
        return v;
    }
}
