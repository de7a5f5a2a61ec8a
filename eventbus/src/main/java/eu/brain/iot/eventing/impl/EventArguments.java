package eu.brain.iot.eventing.impl;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * The fields of an event typed on the command line ({@code bus:publish TYPE key=value ...}) as the map of an
 * untyped event. Values: integers ({@code Integer}, or {@code Long} when too large), decimals ({@code Double}),
 * {@code true}/{@code false}, anything else a string; surrounding quotes are removed. A dotted key
 * ({@code at.x=3}) fills a nested data object ({@code at} becomes a map). Lists are not supported.
 */
final class EventArguments {

    private static final Pattern INTEGER = Pattern.compile("[-+]?\\d+");
    private static final Pattern DECIMAL = Pattern.compile("[-+]?(\\d+\\.\\d*|\\.\\d+|\\d+)([eE][-+]?\\d+)?");
    private static final Pattern KEY = Pattern.compile("[A-Za-z_$][A-Za-z0-9_$]*(\\.[A-Za-z_$][A-Za-z0-9_$]*)*");

    private EventArguments() {
    }

    /** @throws IllegalArgumentException saying which argument is wrong and how to write it */
    static Map<String, Object> parse(String... arguments) {
        Map<String, Object> fields = new LinkedHashMap<>();
        for (int i = 0; i < arguments.length; i++) {
            String argument = arguments[i];
            int eq = argument.indexOf('=');
            String key = eq < 0 ? argument : argument.substring(0, eq);
            if (eq < 0 || !KEY.matcher(key).matches()) {
                throw new IllegalArgumentException("field " + (i + 1) + " \"" + argument + "\" is not key=value "
                        + "with a Java field name as key (nested: at.x=3)");
            }
            put(fields, key, value(argument.substring(eq + 1)), argument);
        }
        return fields;
    }

    @SuppressWarnings("unchecked")
    private static void put(Map<String, Object> fields, String key, Object value, String argument) {
        String[] path = key.split("\\.");
        Map<String, Object> map = fields;
        for (int i = 0; i < path.length - 1; i++) {
            Object nested = map.computeIfAbsent(path[i], k -> new LinkedHashMap<String, Object>());
            if (!(nested instanceof Map)) {
                throw new IllegalArgumentException("\"" + argument + "\": " + path[i] + " was already given a value");
            }
            map = (Map<String, Object>) nested;
        }
        if (map.put(path[path.length - 1], value) != null) {
            throw new IllegalArgumentException("\"" + argument + "\": " + key + " is given twice");
        }
    }

    static Object value(String text) {
        if (text.length() >= 2 && (text.startsWith("\"") && text.endsWith("\"")
                || text.startsWith("'") && text.endsWith("'"))) {
            return text.substring(1, text.length() - 1);
        }
        if (text.equals("true") || text.equals("false")) {
            return Boolean.valueOf(text);
        }
        if (INTEGER.matcher(text).matches()) {
            try {
                long value = Long.parseLong(text);
                return value == (int) value ? (Object) (int) value : (Object) value;
            } catch (NumberFormatException tooLarge) {
                return text;
            }
        }
        if (DECIMAL.matcher(text).matches()) {
            return Double.valueOf(text);
        }
        return text;
    }
}
