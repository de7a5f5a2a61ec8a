package eu.brain.iot.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** The bundles of a node as its Gogo command {@code lb -s} lists them. Stateless. */
final class Bundles {
    /** {@code lb -s} rows: {@code    42|Active     |    1|eu.brain.iot.behaviours.robot (0.1.0.SNAPSHOT)}. */
    private static final Pattern ROW = Pattern.compile("^\\s*(\\d+)\\|(\\w+)\\s*\\|\\s*\\d+\\|(\\S+).*$");
    /** The project's behaviours' symbolic names start so. */
    static final String BEHAVIOUR_PREFIX = "eu.brain.iot.behaviours.";
    static final String ACTIVE = "Active";

    private Bundles() {
    }

    /** A bundle as {@code lb -s} shows it. */
    record Bundle(long id, String state, String symbolicName) {
    }

    static List<Bundle> parse(List<String> lines) {
        List<Bundle> bundles = new ArrayList<>();
        for (String line : lines) {
            Matcher m = ROW.matcher(line);
            if (m.matches()) {
                bundles.add(new Bundle(Long.parseLong(m.group(1)), m.group(2), m.group(3)));
            }
        }
        return bundles;
    }

    /** The symbolic names of the active behaviour bundles ({@value #BEHAVIOUR_PREFIX}...), sorted. */
    static List<String> activeBehaviours(List<Bundle> bundles) {
        return bundles.stream().filter(b -> b.state().equals(ACTIVE))
                .map(Bundle::symbolicName).filter(n -> n.startsWith(BEHAVIOUR_PREFIX)).sorted().toList();
    }
}
