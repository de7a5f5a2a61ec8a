package eu.brain.iot.scenario;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** Durations of warehouse time written as {@code 90s}, {@code 1.5min}, {@code 500ms} or {@code 2h}; and printing. */
final class WarehouseTime {
    private static final Pattern DURATION = Pattern.compile("(\\d+(?:\\.\\d+)?)(ms|s|min|h)");

    private WarehouseTime() {
    }

    /** @throws IllegalArgumentException saying how to write it */
    static long parseMillis(String text) {
        Matcher m = DURATION.matcher(text.trim());
        if (!m.matches()) {
            throw new IllegalArgumentException("'" + text + "' is not a duration: write a number and a unit, "
                    + "ms, s, min or h (90s, 1.5min)");
        }
        double n = Double.parseDouble(m.group(1));
        double factor = switch (m.group(2)) {
            case "ms" -> 1;
            case "s" -> 1_000;
            case "min" -> 60_000;
            default -> 3_600_000;
        };
        return Math.round(n * factor);
    }

    /** {@code 12.5 s}, {@code 3 min 20.0 s}. */
    static String format(long millis) {
        if (millis < 60_000) {
            return String.format(Locale.ROOT, "%.1f s", millis / 1000.0);
        }
        return String.format(Locale.ROOT, "%d min %04.1f s", millis / 60_000, (millis % 60_000) / 1000.0);
    }
}
