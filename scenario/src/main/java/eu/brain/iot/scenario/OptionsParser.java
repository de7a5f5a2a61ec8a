package eu.brain.iot.scenario;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** Reads the command line into {@link Options}; every mistake is a {@link UsageException} saying what to write. */
final class OptionsParser {
    static final String USAGE = """
            Usage: ./warehouse-scenario [options]
            Runs the warehouse end to end: robot-sim and a bare fabric node whose behaviours are installed on demand;
            judges REQ-1 and REQ-2 on robot-sim's ground truth. Exit 0: passed; 1: failed or deadline; 2: bad options.
              --map FILE               warehouse map (default: the paper's: 3 robots, 3 carts, one door)
              --generate               a generated warehouse instead; with
                --width N --height N   (60 x 30)
                --robots N --carts N   (30, 60)
                --doors N              (width/40, at least 1: one door for 60 cells)
              --seed N                 robot-sim's seed, and the generated map's (1)
              --speed F                warehouse time runs F times faster than wall time (10)
              --wait-limit SECONDS     REQ-2: longest wait of a robot behind another, warehouse s (10)
              --deadline MINUTES       warehouse minutes before an unfinished run fails (30, or 3 per cart if more)
              --fault-offline R@T+D    robot R offline at warehouse time T for D, e.g. robot2@60s+30s (repeatable)
              --stop-behaviour B@T     stop behaviour bundle B (robot, door, orchestrator) at T, e.g. robot@90s
              --node-config FILE       a .cfg/.config file for the node's Config Admin, e.g. behaviour settings
                                       (repeatable; copied into the run's node configuration folder)
              --no-behaviours          the node gets no behaviour repository: nothing drives the robots
              --traffic                the fleet's traffic planner drives the robots along reserved paths
                                       (the robot behaviour's traffic=true; behaviours/README.md, "Traffic")
              --run-dir DIR            the run's folder (scenario/target/runs/<date-time>)
              --report FILE            the JSON report (<run-dir>/report.json)
              --progress SECONDS       wall seconds between two progress lines (2)
              --root DIR               the repository root (.)
            Example: ./warehouse-scenario --generate --robots 30 --carts 60 --fault-offline robot2@60s+30s
            """;

    private static final Set<String> VALUED = Set.of("map", "width", "height", "robots", "carts", "doors", "seed",
            "speed", "wait-limit", "deadline", "fault-offline", "stop-behaviour", "node-config", "run-dir", "report",
            "progress", "root");
    private static final Set<String> REPEATABLE = Set.of("fault-offline", "stop-behaviour", "node-config");
    private static final Set<String> SWITCHES = Set.of("generate", "no-behaviours", "traffic", "help");

    private final Map<String, List<String>> values = new HashMap<>();
    private final Set<String> switches = new java.util.HashSet<>();

    private OptionsParser() {
    }

    /** @return the options, or null when help was asked for */
    static Options parse(String... args) throws UsageException {
        OptionsParser p = new OptionsParser();
        p.read(args);
        return p.switches.contains("help") ? null : p.options();
    }

    private void read(String[] args) throws UsageException {
        for (int i = 0; i < args.length; i++) {
            String arg = args[i];
            if (arg.equals("-h")) {
                arg = "--help";
            }
            if (!arg.startsWith("--")) {
                throw new UsageException("unexpected argument '" + arg + "' (options start with --)");
            }
            String name = arg.substring(2);
            if (SWITCHES.contains(name)) {
                switches.add(name);
            } else if (VALUED.contains(name)) {
                if (i + 1 >= args.length) {
                    throw new UsageException("--" + name + " needs a value");
                }
                List<String> list = values.computeIfAbsent(name, k -> new ArrayList<>());
                if (!list.isEmpty() && !REPEATABLE.contains(name)) {
                    throw new UsageException("--" + name + " given twice");
                }
                list.add(args[++i]);
            } else {
                throw new UsageException("unknown option '" + arg + "'");
            }
        }
    }

    private Options options() throws UsageException {
        Path root = Path.of(text("root", System.getProperty("scenario.root", "."))).toAbsolutePath().normalize();
        boolean generate = switches.contains("generate");
        Path map = values.containsKey("map") ? Path.of(text("map", null)) : null;
        if (generate && map != null) {
            throw new UsageException("--map and --generate exclude each other: a map file, or a generated one");
        }
        if (!generate) {
            for (String g : List.of("width", "height", "robots", "carts", "doors")) {
                if (values.containsKey(g)) {
                    throw new UsageException("--" + g + " needs --generate (it sizes a generated warehouse)");
                }
            }
        }
        if (map != null && !Files.isRegularFile(map)) {
            throw new UsageException("--map " + map + ": no such file");
        }
        Options.Generate gen = null;
        int carts = 3;
        if (generate) {
            int width = integer("width", 60, 7, 5000);
            gen = new Options.Generate(width, integer("height", 30, 12, 5000), integer("robots", 30, 1, 100_000),
                    integer("carts", 60, 1, 1_000_000), integer("doors", Math.max(1, width / 40), 1, 10_000));
            carts = gen.carts();
        }
        long seed = longValue("seed", 1);
        double speed = decimal("speed", 10, 0.1, 1000);
        long waitLimitMs = Math.round(decimal("wait-limit", 10, 0.5, 3600) * 1000);
        long deadlineMs = Math.round(decimal("deadline", Math.max(30, 3 * carts), 0.01, 100_000) * 60_000);
        List<PlannedFault> faults = new ArrayList<>();
        try {
            for (String spec : values.getOrDefault("fault-offline", List.of())) {
                faults.add(PlannedFault.Offline.parse(spec));
            }
            for (String spec : values.getOrDefault("stop-behaviour", List.of())) {
                faults.add(PlannedFault.StopBehaviour.parse(spec));
            }
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        List<Path> nodeConfigs = new ArrayList<>();
        for (String file : values.getOrDefault("node-config", List.of())) {
            Path p = Path.of(file);
            String name = p.getFileName().toString();
            if (!Files.isRegularFile(p) || !(name.endsWith(".cfg") || name.endsWith(".config"))) {
                throw new UsageException("--node-config " + file + ": not a readable .cfg or .config file");
            }
            nodeConfigs.add(p.toAbsolutePath());
        }
        Path runDir = values.containsKey("run-dir") ? Path.of(text("run-dir", null)).toAbsolutePath()
                : root.resolve("scenario/target/runs")
                        .resolve(LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")));
        Path report = values.containsKey("report") ? Path.of(text("report", null)).toAbsolutePath()
                : runDir.resolve("report.json");
        long progressMs = Math.round(decimal("progress", 2, 0.1, 3600) * 1000);
        return new Options(root, map, gen, seed, speed, waitLimitMs, deadlineMs, List.copyOf(faults), runDir, report,
                progressMs, !switches.contains("no-behaviours"), List.copyOf(nodeConfigs), switches.contains("traffic"));
    }

    private String text(String name, String fallback) {
        List<String> v = values.get(name);
        return v == null ? fallback : v.get(0);
    }

    private int integer(String name, int fallback, int min, int max) throws UsageException {
        return (int) whole(name, fallback, min, max);
    }

    private long longValue(String name, long fallback) throws UsageException {
        return whole(name, fallback, Long.MIN_VALUE, Long.MAX_VALUE);
    }

    private long whole(String name, long fallback, long min, long max) throws UsageException {
        return number(name, fallback, min, max, Long::parseLong, "a whole number");
    }

    private double decimal(String name, double fallback, double min, double max) throws UsageException {
        return number(name, fallback, min, max, Double::parseDouble, "a number");
    }

    private <T extends Comparable<T>> T number(String name, T fallback, T min, T max,
                                               java.util.function.Function<String, T> parse, String kind)
            throws UsageException {
        String v = text(name, null);
        if (v == null) {
            return fallback;
        }
        try {
            T n = parse.apply(v);
            if (n.compareTo(min) >= 0 && n.compareTo(max) <= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new UsageException("--" + name + " must be " + kind + " " + min + ".." + max + ", found '" + v + "'");
    }
}
