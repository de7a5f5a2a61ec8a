package eu.brain.iot.scenario;

import java.io.IOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.MaxValuesExceededException;
import picocli.CommandLine.MissingParameterException;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.OverwrittenOptionException;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.UnmatchedArgumentException;

import eu.brain.iot.federation.impl.FabricKey;

/**
 * Reads the command line (picocli) into {@link Options}; every mistake is a {@link UsageException} saying what to
 * write. Values are checked after parsing, in a fixed order, so that the first mistake reported does not depend on
 * the order of the options.
 */
@Command(name = "warehouse-scenario", sortOptions = false, usageHelpWidth = 120,
        customSynopsis = "./warehouse-scenario [options]",
        description = {
            "Runs the warehouse end to end: robot-sim and a bare fabric node whose behaviours are installed on demand;",
            "judges REQ-1 and REQ-2 on robot-sim's ground truth. Exit 0: passed; 1: failed or deadline; 2: bad options."},
        footer = "Example: ./warehouse-scenario --generate --robots 30 --carts 60 --fault-offline robot2@60s+30s")
final class OptionsParser {
    /**
     * Warehouse time per wall time unless {@code --speed} says otherwise: a step (0.5 s) is then 100 ms of wall time,
     * in which the fabric polls the fleet, plans it and sends its commands even on two cores shared with robot-sim.
     */
    static final double DEFAULT_SPEED = 5;
    /**
     * The speed with {@code --kill-node} unless {@code --speed} says otherwise: a killed node's robots stand still
     * until its lease lapses and another node takes them, about 2.5 s of wall time; that is 5 s of warehouse time at
     * this speed, but 12.5 s at {@link #DEFAULT_SPEED}, beyond REQ-2's 10 s limit for the robots behind them.
     */
    static final double KILL_DEFAULT_SPEED = 2;
    /** picocli's message for {@code --switch=value}. */
    private static final Pattern SWITCH_WITH_VALUE =
            Pattern.compile("option '(--[^']+)' should be specified without");

    /** The usage text, as {@code --help} prints it. */
    static final String USAGE = new CommandLine(new OptionsParser()).getUsageMessage();

    @Option(names = "--map", paramLabel = "FILE", order = 1,
            description = "warehouse map (default: the paper's: 3 robots, 3 carts, one door)")
    private String map;
    @Option(names = "--generate", arity = "0", order = 2, description = "a generated warehouse instead, sized by:")
    private boolean generate;
    @Option(names = "--width", paramLabel = "N", order = 3, description = "  cells across (60)")
    private String width;
    @Option(names = "--height", paramLabel = "N", order = 4, description = "  cells down (30)")
    private String height;
    @Option(names = "--robots", paramLabel = "N", order = 5, description = "  robots (30)")
    private String robots;
    @Option(names = "--carts", paramLabel = "N", order = 6, description = "  carts (60)")
    private String carts;
    @Option(names = "--doors", paramLabel = "N", order = 7,
            description = "  doors (width/40, at least 1: one door for 60 cells)")
    private String doors;
    @Option(names = "--seed", paramLabel = "N", order = 8, description = "robot-sim's seed, and the generated map's (1)")
    private String seed;
    @Option(names = "--speed", paramLabel = "F", order = 9,
            description = "warehouse time runs F times faster than wall time (5; with --kill-node, 2)")
    private String speed;
    @Option(names = "--wait-limit", paramLabel = "SECONDS", order = 10,
            description = "REQ-2: longest wait of a robot behind another, warehouse s (10)")
    private String waitLimit;
    @Option(names = "--deadline", paramLabel = "MINUTES", order = 11,
            description = "warehouse minutes before an unfinished run fails (30, or 3 per cart if more)")
    private String deadline;
    @Option(names = "--fault-offline", paramLabel = "R@T+D", order = 12,
            description = "robot R offline at warehouse time T for D, e.g. robot2@15s+6s (repeatable)")
    private List<String> faultOffline = new ArrayList<>();
    @Option(names = "--stop-behaviour", paramLabel = "B@T", order = 13, description = {
        "stop behaviour bundle B at T, e.g. robot@25s (repeatable); B is robot, door or",
        "orchestrator, or a bundle's full symbolic name (with a dot)"})
    private List<String> stopBehaviour = new ArrayList<>();
    @Option(names = "--node-config", paramLabel = "FILE", order = 14, description = {
        "a .cfg/.config file for the node's Config Admin, e.g. behaviour settings",
        "(repeatable; copied into the run's node configuration folder)"})
    private List<String> nodeConfig = new ArrayList<>();
    @Option(names = "--no-behaviours", arity = "0", order = 15,
            description = "the node gets no behaviour repository: nothing drives the robots")
    private boolean noBehaviours;
    @Option(names = "--traffic", arity = "0", order = 15, description = {
        "the fleet's traffic planner drives the robots along reserved paths: the default",
        "(the robot behaviour's traffic=true; behaviours/README.md, \"Traffic\")"})
    private boolean traffic;
    @Option(names = "--no-traffic", arity = "0", order = 15, description = {
        "robot-sim plans each go-to and the orchestrator resolves meetings, robots released in waves",
        "(the robot behaviour's traffic=false)"})
    private boolean noTraffic;
    @Option(names = "--nodes", paramLabel = "N", order = 15, description = {
        "a fabric of N nodes, node1..nodeN, each its own JVM owning its share of the fleet",
        "(1.." + Options.MAX_NODES + ", default 1: one node alone); with 2 or more the run starts the embedded",
        "broker unless --broker is given"})
    private String nodes;
    @Option(names = "--kill-node", paramLabel = "NODE@T[+D]", order = 15, description = {
        "kill node NODE's JVM outright (kill -9) at warehouse time T, e.g. node2@20s;",
        "with +D, start it again D later (node2@20s+30s): it rejoins and gets its share back",
        "(repeatable; needs --nodes 2 or more)"})
    private List<String> killNode = new ArrayList<>();
    @Option(names = "--broker", paramLabel = "URI", order = 15, description = {
        "the nodes join a fabric of nodes through this MQTT 5 broker, e.g. tcp://127.0.0.1:1883",
        "(federation/README.md); without it one node runs alone, several join the embedded broker"})
    private String broker;
    @Option(names = "--fabric-key", paramLabel = "FILE", order = 15, description = {
        "the fabric's signing key, shared by its nodes (with --broker or --nodes; default: a new",
        "key in the run's folder)"})
    private String fabricKey;
    @Option(names = "--run-dir", paramLabel = "DIR", order = 16,
            description = "the run's folder, where no run was (scenario/target/runs/<date-time>)")
    private String runDir;
    @Option(names = "--report", paramLabel = "FILE", order = 17, description = "the JSON report (<run-dir>/report.json)")
    private String report;
    @Option(names = "--progress", paramLabel = "SECONDS", order = 18,
            description = "wall seconds between two progress lines (2)")
    private String progress;
    @Option(names = "--root", paramLabel = "DIR", order = 19, description = "the repository root (.)")
    private String root;
    @Option(names = {"--help", "-h"}, usageHelp = true, order = 20, description = "show this help")
    private boolean help;

    private OptionsParser() {
    }

    /** @return the options, or null when help was asked for */
    static Options parse(String... args) throws UsageException {
        OptionsParser p = new OptionsParser();
        CommandLine commandLine = new CommandLine(p);
        try {
            commandLine.parseArgs(args);
        } catch (ParameterException e) {
            throw new UsageException(message(e));
        }
        return commandLine.isUsageHelpRequested() ? null : p.options();
    }

    /** The one line for a command line picocli could not read. */
    private static String message(ParameterException e) {
        if (e instanceof UnmatchedArgumentException u && !u.getUnmatched().isEmpty()) {
            String first = u.getUnmatched().get(0);
            return first.startsWith("--") && first.length() > 2 ? "unknown option '" + first + "'"
                    : "unexpected argument '" + first + "' (options start with --)";
        }
        if (e instanceof MissingParameterException m && !m.getMissing().isEmpty()
                && m.getMissing().get(0) instanceof OptionSpec o) {
            return o.longestName() + " needs a value: " + o.paramLabel()
                    + (o.description().length > 0 ? ", " + o.description()[0] : "");
        }
        if (e instanceof OverwrittenOptionException o && o.getOverwritten() instanceof OptionSpec option) {
            return option.longestName() + " given twice";
        }
        if (e instanceof MaxValuesExceededException) {
            Matcher m = SWITCH_WITH_VALUE.matcher(e.getMessage());
            if (m.find()) {
                return m.group(1) + " takes no value";
            }
        }
        return e.getMessage();
    }

    private Options options() throws UsageException {
        Path rootDir = Path.of(root != null ? root : System.getProperty("scenario.root", ".")).toAbsolutePath()
                .normalize();
        Path mapFile = map != null ? Path.of(map) : null;
        if (generate && mapFile != null) {
            throw new UsageException("--map and --generate exclude each other: a map file, or a generated one");
        }
        if (!generate) {
            String[] sizes = {width, height, robots, carts, doors};
            String[] names = {"width", "height", "robots", "carts", "doors"};
            for (int i = 0; i < sizes.length; i++) {
                if (sizes[i] != null) {
                    throw new UsageException("--" + names[i] + " needs --generate (it sizes a generated warehouse)");
                }
            }
        }
        if (mapFile != null && !Files.isRegularFile(mapFile)) {
            throw new UsageException("--map " + mapFile + ": no such file");
        }
        Options.Generate gen = null;
        int cartCount = 3;
        if (generate) {
            int w = integer("width", width, 60, 7, 5000);
            gen = new Options.Generate(w, integer("height", height, 30, 12, 5000),
                    integer("robots", robots, 30, 1, 100_000), integer("carts", carts, 60, 1, 1_000_000),
                    integer("doors", doors, Math.max(1, w / 40), 1, 10_000));
            cartCount = gen.carts();
        }
        long seedValue = whole("seed", seed, 1, Long.MIN_VALUE, Long.MAX_VALUE);
        double speedValue = decimal("speed", speed, killNode.isEmpty() ? DEFAULT_SPEED : KILL_DEFAULT_SPEED, 0.1,
                1000);
        long waitLimitMs = Math.round(decimal("wait-limit", waitLimit, 10, 0.5, 3600) * 1000);
        long deadlineMs = Math.round(decimal("deadline", deadline, Math.max(30, 3 * cartCount), 0.01, 100_000)
                * 60_000);
        int nodeCount = integer("nodes", nodes, 1, 1, Options.MAX_NODES);
        List<PlannedFault> faults = new ArrayList<>();
        try {
            for (String spec : faultOffline) {
                faults.add(PlannedFault.Offline.parse(spec));
            }
            for (String spec : stopBehaviour) {
                faults.add(PlannedFault.StopBehaviour.parse(spec));
            }
            List<PlannedFault.KillNode> kills = new ArrayList<>();
            for (String spec : killNode) {
                PlannedFault.KillNode kill = PlannedFault.KillNode.parse(spec);
                kill.checkNodes(nodeCount);
                kills.add(kill);
            }
            PlannedFault.KillNode.checkTogether(kills, nodeCount);
            faults.addAll(kills);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        List<Path> nodeConfigs = new ArrayList<>();
        for (String file : nodeConfig) {
            Path p = Path.of(file);
            String name = p.getFileName().toString();
            if (!Files.isRegularFile(p) || !(name.endsWith(".cfg") || name.endsWith(".config"))) {
                throw new UsageException("--node-config " + file + ": not a readable .cfg or .config file");
            }
            nodeConfigs.add(p.toAbsolutePath());
        }
        Options.Fabric fabric = fabric(nodeCount);
        Path runFolder = runDir != null ? Path.of(runDir).toAbsolutePath()
                : rootDir.resolve("scenario/target/runs")
                        .resolve(LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")));
        if (runDir != null && holdsARun(runFolder)) {
            throw new UsageException("--run-dir " + runDir + ": the folder holds an earlier run (its journal would"
                    + " bring that run's behaviours back, and the nodes would not start bare): remove it, or choose a"
                    + " folder where no run was");
        }
        Path reportFile = report != null ? Path.of(report).toAbsolutePath() : runFolder.resolve("report.json");
        long progressMs = Math.round(decimal("progress", progress, 2, 0.1, 3600) * 1000);
        if (traffic && noTraffic) {
            throw new UsageException("--traffic and --no-traffic: choose one");
        }
        return new Options(rootDir, mapFile, gen, seedValue, speedValue, waitLimitMs, deadlineMs, List.copyOf(faults),
                runFolder, reportFile, progressMs, !noBehaviours, List.copyOf(nodeConfigs), !noTraffic, fabric,
                nodeCount);
    }

    /** What a run leaves in its folder (a node's, or each node's in {@code nodeK}): any of them, a run was there. */
    private static final Pattern RUN_OUTPUT = Pattern.compile("journal|state|federation|node-config|node\\.log"
            + "|report\\.json|node\\d+");

    /** @return whether the folder holds what an earlier run left (other files may be there: a broker's, say) */
    private static boolean holdsARun(Path folder) throws UsageException {
        if (!Files.isDirectory(folder)) {
            return false;
        }
        try (var entries = Files.list(folder)) {
            return entries.anyMatch(e -> RUN_OUTPUT.matcher(e.getFileName().toString()).matches());
        } catch (IOException e) {
            throw new UsageException("--run-dir " + folder + ": cannot be read (" + e.getMessage() + ")");
        }
    }

    /**
     * {@code --broker} and {@code --fabric-key}, checked: a URI a fabric node connects to, a readable key. One node
     * joins a fabric only with {@code --broker}, in the fabric {@value Options.Fabric#NAME}; several always do, in a
     * fabric named for the run ({@code warehouse-} and 8 random hex digits), through the embedded broker when no URI
     * is given.
     */
    private Options.Fabric fabric(int nodeCount) throws UsageException {
        if (broker == null && nodeCount < 2) {
            if (fabricKey != null) {
                throw new UsageException("--fabric-key needs --broker or --nodes 2 or more (the key signs what the "
                        + "nodes send through the broker)");
            }
            return null;
        }
        Path key = fabricKey();
        if (broker == null) {
            return new Options.Fabric(null, key, runFabricName());
        }
        URI uri;
        try {
            uri = new URI(broker);
        } catch (URISyntaxException e) {
            uri = null;
        }
        if (uri == null || !("tcp".equals(uri.getScheme()) || "ssl".equals(uri.getScheme())) || uri.getHost() == null
                || uri.getPort() < 1 || uri.getPort() > MAX_PORT) {
            throw new UsageException("--broker must be an MQTT broker's URI with its port (1.." + MAX_PORT + "), e.g. "
                    + "tcp://127.0.0.1:1883 or ssl://broker.example:8883, found '" + broker + "'");
        }
        return nodeCount < 2 ? new Options.Fabric(broker, key) : new Options.Fabric(broker, key, runFabricName());
    }

    /** {@code --fabric-key}: a readable file, or null for a new key. */
    private Path fabricKey() throws UsageException {
        if (fabricKey == null) {
            return null;
        }
        Path key = Path.of(fabricKey).toAbsolutePath();
        if (!Files.isRegularFile(key) || !Files.isReadable(key)) {
            throw new UsageException("--fabric-key " + fabricKey + ": no such readable file (make one with "
                    + "fabric:keygen in a node's shell, or leave the option out for a new key)");
        }
        try {
            FabricKey.read(key); // read as every node reads it, so that a bad key stops the run here, not its nodes
        } catch (IOException e) {
            throw new UsageException("--fabric-key " + fabricKey + ": " + e.getMessage());
        }
        return key;
    }

    /** The highest TCP port. */
    private static final int MAX_PORT = 65_535;

    /** A fabric name of this run's own, so that nodes of another run on the same broker never meet these. */
    private static String runFabricName() {
        return Options.Fabric.NAME + "-" + String.format("%08x", new java.security.SecureRandom().nextInt());
    }

    private static int integer(String name, String text, int fallback, int min, int max) throws UsageException {
        return (int) whole(name, text, fallback, min, max);
    }

    /** A whole number in {@code min..max}; the range is left out of the message when it is all of {@code long}. */
    private static long whole(String name, String text, long fallback, long min, long max) throws UsageException {
        String range = min == Long.MIN_VALUE && max == Long.MAX_VALUE ? "" : " " + min + ".." + max;
        return number(name, text, fallback, min, max, Long::parseLong, "a whole number" + range);
    }

    private static double decimal(String name, String text, double fallback, double min, double max)
            throws UsageException {
        return number(name, text, fallback, min, max, Double::parseDouble, "a number " + min + ".." + max);
    }

    private static <T extends Comparable<T>> T number(String name, String text, T fallback, T min, T max,
                                                      Function<String, T> parse, String kind)
            throws UsageException {
        if (text == null) {
            return fallback;
        }
        try {
            T n = parse.apply(text);
            if (n.compareTo(min) >= 0 && n.compareTo(max) <= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new UsageException("--" + name + " must be " + kind + ", found '" + text + "'");
    }
}
