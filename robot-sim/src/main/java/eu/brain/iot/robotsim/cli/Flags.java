package eu.brain.iot.robotsim.cli;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A strict reader of {@code --name value}, {@code --name=value} and {@code --switch} arguments. Every getter
 * checks its value and throws a {@link UsageException} naming the flag.
 */
public final class Flags {
    private final Map<String, List<String>> values = new LinkedHashMap<>();

    private Flags() {
    }

    /**
     * @param withValue flags that take a value (may repeat)
     * @param switches  flags without a value
     */
    public static Flags parse(String[] args, Set<String> withValue, Set<String> switches) throws UsageException {
        Flags flags = new Flags();
        for (int i = 0; i < args.length; i++) {
            String arg = args[i];
            if (!arg.startsWith("--") || arg.length() == 2) {
                throw new UsageException("unexpected argument '" + arg + "'");
            }
            String name = arg.substring(2);
            String value = null;
            int eq = name.indexOf('=');
            if (eq >= 0) {
                value = name.substring(eq + 1);
                name = name.substring(0, eq);
            }
            if (switches.contains(name)) {
                if (value != null) {
                    throw new UsageException("--" + name + " takes no value");
                }
                flags.values.computeIfAbsent(name, k -> new ArrayList<>()).add("true");
            } else if (withValue.contains(name)) {
                if (value == null) {
                    if (i + 1 >= args.length || args[i + 1].startsWith("--")) {
                        throw new UsageException("--" + name + " needs a value");
                    }
                    value = args[++i];
                }
                flags.values.computeIfAbsent(name, k -> new ArrayList<>()).add(value);
            } else {
                throw new UsageException("unknown option --" + name);
            }
        }
        return flags;
    }

    public boolean has(String name) {
        return values.containsKey(name);
    }

    public List<String> all(String name) {
        return values.getOrDefault(name, List.of());
    }

    public String string(String name, String fallback) throws UsageException {
        List<String> v = values.get(name);
        if (v == null) {
            return fallback;
        }
        if (v.size() > 1) {
            throw new UsageException("--" + name + " given " + v.size() + " times");
        }
        return v.get(0);
    }

    public long longValue(String name, long fallback, long min, long max) throws UsageException {
        String s = string(name, null);
        if (s == null) {
            return fallback;
        }
        try {
            long n = Long.parseLong(s.strip());
            if (n >= min && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new UsageException("--" + name + " must be a whole number " + min + ".." + max + ", found '" + s + "'");
    }

    public int intValue(String name, int fallback, int min, int max) throws UsageException {
        return (int) longValue(name, fallback, min, max);
    }

    public double doubleValue(String name, double fallback, double minExclusive, double max) throws UsageException {
        String s = string(name, null);
        if (s == null) {
            return fallback;
        }
        try {
            double d = Double.parseDouble(s.strip());
            if (d > minExclusive && d <= max) {
                return d;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new UsageException("--" + name + " must be a number > " + minExclusive + " and <= " + max
                + ", found '" + s + "'");
    }
}
