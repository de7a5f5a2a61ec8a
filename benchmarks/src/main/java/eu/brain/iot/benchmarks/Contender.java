package eu.brain.iot.benchmarks;

import java.io.Serializable;
import java.util.List;
import java.util.Map;

/**
 * One bus under test: the bundles installed into its own Felix framework, in this order, and the framework
 * properties it runs with. Bundle names are file names in the bundles directory (see pom.xml).
 *
 * @param key the command-line name
 * @param label the name in the result table
 */
record Contender(String key, String label, List<String> bundles, Map<String, String> frameworkProperties)
        implements Serializable {

    private static final List<String> OSGI_UTIL = List.of("org.osgi.util.function.jar", "org.osgi.util.promise.jar",
            "org.osgi.util.converter.jar");

    /** Every contender, peers first (by default each runs in a JVM of its own, so the order does not matter). */
    static List<Contender> all() {
        List<String> eventAdmin = List.of("org.apache.felix.eventadmin.jar", "benchmarks-driver-eventadmin.jar");
        return List.of(
                new Contender("eventadmin", "Felix EventAdmin 1.6.4 postEvent (default)", eventAdmin, Map.of()),
                new Contender("eventadmin-t0", "Felix EventAdmin 1.6.4 postEvent (Timeout=0)", eventAdmin,
                        Map.of("org.apache.felix.eventadmin.Timeout", "0")),
                new Contender("aries", "Aries typedevent bus 0.0.2 deliver", concat(OSGI_UTIL,
                        List.of("org.osgi.util.pushstream.jar", "org.osgi.service.typedevent.jar",
                                "org.apache.felix.configadmin.jar", "org.apache.aries.component-dsl.component-dsl.jar",
                                "slf4j-api.jar", "slf4j-simple.jar", "org.apache.aries.typedevent.bus.jar",
                                "benchmarks-driver-typedevent.jar")),
                        Map.of()),
                new Contender("ours", "BRAIN-IoT eventbus deliver", concat(OSGI_UTIL,
                        List.of("org.apache.felix.log.jar", "org.osgi.service.component.jar", "org.apache.felix.scr.jar", "eventbus.jar",
                                "benchmarks-driver-ours.jar")),
                        Map.of()));
    }

    private static List<String> concat(List<String> a, List<String> b) {
        return java.util.stream.Stream.concat(a.stream(), b.stream()).toList();
    }
}
