package eu.brain.iot.robotsim.cli;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.SimConfig;
import eu.brain.iot.robotsim.fault.FaultFieldException;
import eu.brain.iot.robotsim.fault.FaultSettings;
import eu.brain.iot.robotsim.world.MapFormatException;
import eu.brain.iot.robotsim.world.MapParser;
import eu.brain.iot.robotsim.world.SimRules;
import eu.brain.iot.robotsim.world.WarehouseMap;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Set;

/** The default command: start the simulator from command-line flags and list its URLs. */
public final class ServeCommand {
    public static final int DEFAULT_PORT = 8090;

    static final String USAGE = """
            Usage: java -jar robot-sim.jar [options]           start the simulated warehouse
                   java -jar robot-sim.jar generate --help     write a large warehouse map
                   java -jar robot-sim.jar poll-load --help    load test: poll every robot's state
                   java -jar robot-sim.jar step-bench --help   time simulation steps
            Options:
              --port N             port to listen on (default 8090; 0 = any free port)
              --bind ADDR          address to listen on (default 127.0.0.1)
              --map FILE           warehouse map file (default: the paper's warehouse, 3 robots, 3 carts, 1 door)
              --seed N             seed for tie-breaks between robots (default 1)
              --speed F            speed factor: 100 runs 100 steps per 0.5 s (default 1)
              --step-ms N          warehouse time of one step in ms (default 500)
              --manual-step        no clock: steps only on POST /admin/step
              --door-open-steps N  steps a door takes to open (default: as the map says, else 4)
              --deadlock-steps N   steps of waiting in a cycle that count as a deadlock (default 4)
              --fault SPEC         inject faults, repeatable: [ROBOT:]key=value[,key=value...]
                                   keys latencyMs, errorRate, malformedRate, dropRate, offline
                                   e.g. --fault errorRate=0.1   --fault robot2:offline=true
              --io-threads N       HTTP I/O threads (default: one per core)
              --max-queue N        missions a robot may have waiting; one more is refused with 429 (default 64)
              --allow-host NAME    also accept this name in the Host and Origin headers, repeatable (default:
                                   127.0.0.1, localhost, [::1] and the --bind address, each with the port)
              --request-timeout-ms N  time a request may take to arrive whole once begun; then 408 (default 10000)
              --quiet              do not list every robot's and door's URL
              --help               show this help
            """;

    private static final Set<String> VALUED = Set.of("port", "bind", "map", "seed", "speed", "step-ms",
            "door-open-steps", "deadlock-steps", "fault", "io-threads", "max-queue", "allow-host",
            "request-timeout-ms");
    private static final Set<String> SWITCHES = Set.of("manual-step", "quiet", "help");

    private ServeCommand() {
    }

    /** Reads the flags into a configuration; {@code --help} is checked by the caller first. */
    public static SimConfig config(Flags f) throws UsageException {
        SimConfig.Builder b = SimConfig.builder()
                .port(f.intValue("port", DEFAULT_PORT, 0, 65535));
        try {
            b.bindAddress(f.string("bind", "127.0.0.1"));
        } catch (IllegalArgumentException e) {
            throw new UsageException("--bind: " + e.getMessage());
        }
        b.speed(f.doubleValue("speed", 1.0, 0, 10_000))
                .stepMillis(f.intValue("step-ms", SimConfig.DEFAULT_STEP_MILLIS, 1, 3_600_000))
                .manualStep(f.has("manual-step"))
                .ioThreads(f.intValue("io-threads", 0, 0, 256))
                .maxQueuedMissions(f.intValue("max-queue", SimConfig.DEFAULT_MAX_QUEUED_MISSIONS, 1, 1_000_000))
                .requestTimeoutMillis(f.intValue("request-timeout-ms", SimConfig.DEFAULT_REQUEST_TIMEOUT_MILLIS, 100,
                        3_600_000));
        for (String host : f.all("allow-host")) {
            try {
                b.allowHost(host);
            } catch (IllegalArgumentException e) {
                throw new UsageException("--allow-host: " + e.getMessage());
            }
        }
        String mapFile = f.string("map", null);
        if (mapFile != null) {
            b.map(readMap(mapFile));
        }
        SimRules d = SimRules.DEFAULT;
        b.rules(new SimRules(f.longValue("seed", d.seed(), Long.MIN_VALUE, Long.MAX_VALUE), d.pickSteps(),
                d.placeSteps(), f.intValue("deadlock-steps", d.deadlockSteps(), 1, 1_000_000),
                f.intValue("door-open-steps", d.doorOpenSteps(), 0, 1_000_000)));
        for (String spec : f.all("fault")) {
            fault(b, spec);
        }
        return b.build();
    }

    private static WarehouseMap readMap(String file) throws UsageException {
        try {
            return MapParser.parse(Path.of(file));
        } catch (NoSuchFileException e) {
            throw new UsageException("--map: no such file '" + file + "'");
        } catch (IOException e) {
            throw new UsageException("--map: cannot read '" + file + "': " + e.getMessage());
        } catch (MapFormatException e) {
            throw new UsageException("--map: " + e.getMessage());
        }
    }

    /** {@code [ROBOT:]key=value[,key=value...]} */
    static void fault(SimConfig.Builder b, String spec) throws UsageException {
        String robot = null;
        String settings = spec;
        int colon = spec.indexOf(':');
        int eq = spec.indexOf('=');
        if (colon >= 0 && (eq < 0 || colon < eq)) {
            robot = spec.substring(0, colon);
            settings = spec.substring(colon + 1);
        }
        FaultSettings f = FaultSettings.NONE;
        for (String pair : settings.split(",")) {
            int at = pair.indexOf('=');
            if (at <= 0) {
                throw new UsageException("--fault '" + spec + "': expected key=value, found '" + pair + "'");
            }
            try {
                f = f.with(pair.substring(0, at).strip(), pair.substring(at + 1).strip());
            } catch (FaultFieldException e) {
                throw new UsageException("--fault '" + spec + "': " + e.getMessage());
            }
        }
        if (robot == null) {
            b.fleetFaults(f);
        } else {
            b.robotFaults(robot, f);
        }
    }

    /** Parses, starts and prints; returns the running simulator, or throws for a bad command line. */
    static RobotSim start(String[] args, PrintStream out) throws UsageException, IOException {
        Flags flags = Flags.parse(args, VALUED, SWITCHES);
        SimConfig config = config(flags);
        RobotSim sim;
        try {
            sim = RobotSim.start(config);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--fault: " + e.getMessage());
        }
        describe(sim, !flags.has("quiet"), out);
        return sim;
    }

    static boolean wantsHelp(String[] args) {
        for (String a : args) {
            if (a.equals("--help") || a.equals("-h")) {
                return true;
            }
        }
        return false;
    }

    /** Prints what is running and the URL of every robot and door. */
    static void describe(RobotSim sim, boolean listAll, PrintStream out) {
        SimConfig c = sim.config();
        out.printf("robot-sim: warehouse '%s' %dx%d, %d robots, %d carts, %d doors, seed %d, %s%n",
                c.map().name(), c.map().width(), c.map().height(), c.map().robots().size(),
                c.map().carts().size(), c.map().doors().size(), c.rules().seed(),
                c.manualStep() ? "manual steps (POST /admin/step)"
                        : "one step of " + c.stepMillis() + " ms every " + (c.stepPeriodNanos() / 1_000_000.0)
                        + " ms (speed x" + c.speed() + ")");
        out.println("listening on " + sim.baseUri());
        if (listAll) {
            for (String id : sim.robotIds()) {
                out.println("robot " + id + " " + sim.robotStateUri(id));
            }
            for (String id : sim.doorIds()) {
                out.println("door  " + id + " " + sim.doorStateUri(id) + " (command: POST "
                        + sim.doorCommandUri(id) + ")");
            }
        }
        out.println("world " + sim.baseUri().resolve("world"));
        out.flush();
    }
}
