package eu.brain.iot.node.ready;

import java.util.List;

/**
 * The wording of the node's two ready lines, apart from when they are printed ({@link ReadyReporter}): what is up,
 * counted so that a reader does not take a bundle not yet started for a failed one, which levels are reached, why the
 * shell comes last, what to type and how to stop the node.
 */
final class ReadyLines {

    /** The Gogo shell's arguments (a framework property); with {@value #NO_INTERACTIVE} it reads no console. */
    static final String SHELL_ARGS = "gosh.args";
    static final String NO_INTERACTIVE = "--nointeractive";

    private ReadyLines() {
    }

    /**
     * The ready line: {@code fabric node ready in 812 ms (JVM start to event bus up; start level 1: 37 of 41 bundles
     * active, the other 4 start next); try ...}. Fragments and lazy bundles are counted apart (see {@link Census}),
     * and the bundles of the higher levels are said to come next, so that a count below the number installed does
     * not read as a failure.
     */
    static String readyLine(long millis, String waitedFor, int coreLevel, Census census, String howToUse) {
        int later = census.installed() - census.running();
        return String.format("fabric node ready in %d ms (JVM start to event bus%s up; start level %d: %s%s); %s",
                millis, waitedFor, coreLevel, census.describe(),
                later == 0 ? "" : ", " + theOthers(later) + " next", howToUse);
    }

    /**
     * The second line, once every level below the shell's is up: {@code fabric node: start levels 1 and 2 up in
     * 1724 ms (the core, then the edge and its REST API): 40 of 41 bundles active; dashboard: http://...; then
     * level 3: ...} ({@code whatIsNext} starts with the dashboard's link, {@link #dashboard}, when it runs).
     */
    static String upLine(long millis, int level, Census census, String whatIsNext) {
        String levels = level == 1 ? "start level 1"
                : level == 2 ? "start levels 1 and 2" : "start levels 1 to " + level;
        return String.format("fabric node: %s up in %d ms (the core, then the edge and its REST API): %s%s", levels,
                millis, census.describe(), whatIsNext);
    }

    /** The live dashboard's bundle: the second line links its page when it is active. */
    static final String DASHBOARD = "eu.brain.iot.dashboard";
    /** Felix HTTP's framework properties: where it listens (no host: every interface; no port: its default 8080). */
    static final String HTTP_HOST = "org.apache.felix.http.host";
    static final String HTTP_PORT = "org.osgi.service.http.port";

    /**
     * The second line's link to the live dashboard: {@code ; dashboard: http://127.0.0.1:8181/dashboard/}, at the
     * address Felix HTTP is configured with. Bound to every interface (no host, {@code 0.0.0.0}, {@code ::}) it names
     * loopback, which such a bind includes and the node's gate always accepts, and says that other machines use a
     * name of this one.
     */
    static String dashboard(String host, String port) {
        String h = host == null ? "" : host.strip();
        boolean wildcard = h.isEmpty() || h.equals("0.0.0.0") || h.equals("::") || h.equals("[::]") || h.equals("*");
        if (wildcard) {
            h = "127.0.0.1";
        } else if (h.contains(":") && !h.startsWith("[")) {
            h = "[" + h + "]"; // an IPv6 literal in a URL
        }
        String p = port == null || port.isBlank() ? "8080" : port.strip();
        return "; dashboard: http://" + h + ":" + p + "/dashboard/"
                + (wildcard ? " (listening on every interface: from another machine, a name of this one in "
                        + "allowed.hosts)" : "");
    }

    /**
     * The end of the second line: the bundles not active yet (the shell, and bundles dropped in the config folder)
     * and why they come last; a check run stops before them.
     */
    static String whatIsNext(boolean check, String shellArgs, int shellLevel, int later) {
        if (shellLevel <= 0) {
            return later == 0 ? "" : "; " + theOthers(later) + " next";
        }
        if (check) {
            return "; a check run stops here, before level " + shellLevel + " (the Gogo shell)";
        }
        String others = "; " + theOthers(later) + " at level " + shellLevel + ": the Gogo shell";
        if (noConsole(shellArgs)) {
            return others + " (without a console: " + SHELL_ARGS + "=" + NO_INTERACTIVE + ")"
                    + (later > 1 ? " and the config folder's bundles" : "");
        }
        return others + (later > 1 ? " and the config folder's bundles" : "")
                + ", last so that its prompt follows this line";
    }

    private static String theOthers(int count) {
        return count == 1 ? "the other one starts" : "the other " + count + " start";
    }

    static boolean noConsole(String shellArgs) {
        return shellArgs != null && List.of(shellArgs.trim().split("\\s+")).contains(NO_INTERACTIVE);
    }

    /** How the ready line names what it waited for besides the bus. */
    static String describe(List<String> services) {
        List<String> names = new java.util.ArrayList<>();
        for (String service : services) {
            names.add(switch (service) {
            case "eu.brain.iot.bis.api.BundleInstaller" -> "behaviour installer (journal restored)";
            case "eu.brain.iot.eventing.spi.UnhandledEventPolicy" -> "behaviour management";
            default -> service.substring(service.lastIndexOf('.') + 1);
            });
        }
        return String.join(" and ", names);
    }

    /**
     * The end of the ready line: what to type, and how to stop the node. Without an interactive shell (the Gogo
     * shell's {@code --nointeractive}, as {@code ./fabric-node --no-shell} sets) there is nothing to type into:
     * the node runs until its process is stopped.
     */
    static String howToUse(boolean check, String shellArgs, long pid) {
        if (check) {
            return "check run: stops once every bundle is active";
        }
        if (noConsole(shellArgs)) {
            return "no shell (" + SHELL_ARGS + "=" + NO_INTERACTIVE + "): stop it with Ctrl-C or kill " + pid;
        }
        return "try bus:behaviours, bus:publish, bis:list, bms:pending, edge:robots, lb; 'stop 0' quits";
    }
}
