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
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * The default command: start the simulator from command-line options and list its URLs. Its {@link #call()} returns
 * {@link #RUNNING}: the simulator runs until the JVM stops.
 */
@Command(name = "robot-sim", sortOptions = false, usageHelpWidth = 120, subcommands = GenerateCommand.class,
        customSynopsis = {
            "java -jar robot-sim.jar [options]           start the simulated warehouse",
            "       java -jar robot-sim.jar generate --help     write a large warehouse map"},
        optionListHeading = "Options:%n")
public final class ServeCommand implements Callable<Integer> {
    public static final int DEFAULT_PORT = 8090;
    /** What {@link #call()} returns: the server was started and keeps running. */
    public static final int RUNNING = -1;

    @Spec
    private CommandSpec spec;

    private final PrintStream out;
    private RobotSim started;

    private int port = DEFAULT_PORT;
    private String bind = "127.0.0.1";
    private Path map;
    private long seed = SimRules.DEFAULT.seed();
    private double speed = 1.0;
    private int stepMillis = SimConfig.DEFAULT_STEP_MILLIS;
    private Integer doorOpenSteps;
    private int deadlockSteps = SimRules.DEFAULT.deadlockSteps();
    private int ioThreads;
    private int maxQueue = SimConfig.DEFAULT_MAX_QUEUED_MISSIONS;
    private int requestTimeoutMillis = SimConfig.DEFAULT_REQUEST_TIMEOUT_MILLIS;

    @Option(names = "--manual-step", arity = "0", order = 7, description = "no clock: steps only on POST /admin/step")
    private boolean manualStep;

    @Option(names = "--quiet", arity = "0", order = 15, description = "do not list every robot's and door's URL")
    private boolean quiet;

    @Option(names = {"--help", "-h"}, usageHelp = true, order = 16, description = "show this help")
    private boolean help;

    /** @param out where the URLs are listed when the simulator has started */
    public ServeCommand(PrintStream out) {
        this.out = out;
    }

    /** The command line read into a new command, for tests that look at its configuration. */
    static ServeCommand parse(String... args) {
        ServeCommand command = new ServeCommand(System.out);
        new CommandLine(command).parseArgs(args);
        return command;
    }

    @Option(names = "--port", paramLabel = "N", order = 1,
            description = "port to listen on (default 8090; 0 = any free port)")
    void port(String v) {
        port = Values.wholeInt(spec, "--port", v, 0, 65535);
    }

    @Option(names = "--bind", paramLabel = "ADDR", order = 2, description = "address to listen on (default 127.0.0.1)")
    void bind(String v) {
        bind = v;
    }

    @Option(names = "--map", paramLabel = "FILE", order = 3,
            description = "warehouse map file (default: the paper's warehouse, 3 robots, 3 carts, 1 door)")
    void map(String v) {
        map = Path.of(v);
    }

    @Option(names = "--seed", paramLabel = "N", order = 4, description = "seed for tie-breaks between robots (default 1)")
    void seed(String v) {
        seed = Values.whole(spec, "--seed", v, Long.MIN_VALUE, Long.MAX_VALUE);
    }

    @Option(names = "--speed", paramLabel = "F", order = 5,
            description = "speed factor: 100 runs 100 steps per 0.5 s (default 1)")
    void speed(String v) {
        speed = Values.above(spec, "--speed", v, 0, 10_000);
    }

    @Option(names = "--step-ms", paramLabel = "N", order = 6,
            description = "warehouse time of one step in ms (default 500)")
    void stepMillis(String v) {
        stepMillis = Values.wholeInt(spec, "--step-ms", v, 1, 3_600_000);
    }

    @Option(names = "--door-open-steps", paramLabel = "N", order = 8,
            description = "steps a door takes to open (default: as the map says, else 4)")
    void doorOpenSteps(String v) {
        doorOpenSteps = Values.wholeInt(spec, "--door-open-steps", v, 0, 1_000_000);
    }

    @Option(names = "--deadlock-steps", paramLabel = "N", order = 9,
            description = "steps of waiting in a cycle that count as a deadlock (default 4)")
    void deadlockSteps(String v) {
        deadlockSteps = Values.wholeInt(spec, "--deadlock-steps", v, 1, 1_000_000);
    }

    @Option(names = "--fault", paramLabel = "SPEC", order = 10, description = {
        "inject faults, repeatable: [ROBOT:]key=value[,key=value...]",
        "keys latencyMs, errorRate, malformedRate, dropRate, offline",
        "e.g. --fault errorRate=0.1   --fault robot2:offline=true"})
    private List<String> faults = new ArrayList<>();

    @Option(names = "--io-threads", paramLabel = "N", order = 11,
            description = "HTTP I/O threads (default: one per core)")
    void ioThreads(String v) {
        ioThreads = Values.wholeInt(spec, "--io-threads", v, 0, 256);
    }

    @Option(names = "--max-queue", paramLabel = "N", order = 12,
            description = "missions a robot may have waiting; one more is refused with 429 (default 64)")
    void maxQueue(String v) {
        maxQueue = Values.wholeInt(spec, "--max-queue", v, 1, 1_000_000);
    }

    @Option(names = "--allow-host", paramLabel = "NAME", order = 13, description = {
        "also accept this name in the Host and Origin headers, repeatable (default:",
        "127.0.0.1, localhost, [::1] and the --bind address, each with the port)"})
    private List<String> allowHosts = new ArrayList<>();

    @Option(names = "--request-timeout-ms", paramLabel = "N", order = 14,
            description = "time a request may take to arrive whole once begun; then 408 (default 10000)")
    void requestTimeout(String v) {
        requestTimeoutMillis = Values.wholeInt(spec, "--request-timeout-ms", v, 100, 3_600_000);
    }

    /** The options read into a configuration. */
    public SimConfig config() throws UsageException {
        SimConfig.Builder b = SimConfig.builder().port(port);
        try {
            b.bindAddress(bind);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--bind: " + e.getMessage());
        }
        b.speed(speed)
                .stepMillis(stepMillis)
                .manualStep(manualStep)
                .ioThreads(ioThreads)
                .maxQueuedMissions(maxQueue)
                .requestTimeoutMillis(requestTimeoutMillis);
        for (String host : allowHosts) {
            try {
                b.allowHost(host);
            } catch (IllegalArgumentException e) {
                throw new UsageException("--allow-host: " + e.getMessage());
            }
        }
        if (map != null) {
            b.map(readMap(map));
        }
        SimRules d = SimRules.DEFAULT;
        b.rules(new SimRules(seed, d.pickSteps(), d.placeSteps(), deadlockSteps,
                doorOpenSteps != null ? doorOpenSteps : d.doorOpenSteps()));
        for (String faultSpec : faults) {
            fault(b, faultSpec);
        }
        return b.build();
    }

    private static WarehouseMap readMap(Path file) throws UsageException {
        try {
            return MapParser.parse(file);
        } catch (NoSuchFileException e) {
            throw new UsageException("--map: no such file '" + file + "'");
        } catch (IOException e) {
            throw new UsageException("--map: cannot read '" + file + "': " + e.getMessage());
        } catch (MapFormatException e) {
            throw new UsageException("--map: " + e.getMessage());
        }
    }

    /** {@code [ROBOT:]key=value[,key=value...]} */
    static void fault(SimConfig.Builder b, String faultSpec) throws UsageException {
        String robot = null;
        String settings = faultSpec;
        int colon = faultSpec.indexOf(':');
        int eq = faultSpec.indexOf('=');
        if (colon >= 0 && (eq < 0 || colon < eq)) {
            robot = faultSpec.substring(0, colon);
            settings = faultSpec.substring(colon + 1);
        }
        FaultSettings f = FaultSettings.NONE;
        for (String pair : settings.split(",")) {
            int at = pair.indexOf('=');
            if (at <= 0) {
                throw new UsageException("--fault '" + faultSpec + "': expected key=value, found '" + pair + "'");
            }
            try {
                f = f.with(pair.substring(0, at).strip(), pair.substring(at + 1).strip());
            } catch (FaultFieldException e) {
                throw new UsageException("--fault '" + faultSpec + "': " + e.getMessage());
            }
        }
        if (robot == null) {
            b.fleetFaults(f);
        } else {
            b.robotFaults(robot, f);
        }
    }

    /** Starts the simulator and lists its URLs; it keeps running (see {@link #started()}). */
    @Override
    public Integer call() throws UsageException, IOException {
        SimConfig config = config();
        try {
            started = RobotSim.start(config);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--fault: " + e.getMessage());
        }
        describe(started, !quiet, out);
        return RUNNING;
    }

    /** The simulator {@link #call()} started, or null. */
    RobotSim started() {
        return started;
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
