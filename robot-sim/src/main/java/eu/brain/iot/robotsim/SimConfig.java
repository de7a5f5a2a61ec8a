package eu.brain.iot.robotsim;

import eu.brain.iot.robotsim.fault.FaultSettings;
import eu.brain.iot.robotsim.world.Commands;
import eu.brain.iot.robotsim.world.SimRules;
import eu.brain.iot.robotsim.world.WarehouseMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * How to start a simulator. Defaults: the paper's warehouse, seed 1, loopback address, an ephemeral port (the
 * command line uses 8090), one step every 500 ms at speed 1, fault-free, at most 64 queued missions per robot, a request
 * must arrive whole within 10 s, and only loopback names (and the bind address) are accepted in {@code Host}.
 */
public final class SimConfig {
    public static final int DEFAULT_STEP_MILLIS = 500;
    public static final int DEFAULT_MAX_QUEUED_MISSIONS = Commands.DEFAULT_MAX_QUEUED;
    public static final int DEFAULT_REQUEST_TIMEOUT_MILLIS = 10_000;
    /** A host name or IPv4 address; IPv6 addresses are checked apart. */
    private static final Pattern HOST_NAME = Pattern.compile("[A-Za-z0-9]([A-Za-z0-9._-]{0,252})");

    private final WarehouseMap map;
    private final SimRules rules;
    private final String bindAddress;
    private final int port;
    private final int stepMillis;
    private final double speed;
    private final boolean manualStep;
    private final int ioThreads;
    private final FaultSettings fleetFaults;
    private final Map<String, FaultSettings> robotFaults;
    private final int maxQueuedMissions;
    private final int requestTimeoutMillis;
    private final Set<String> allowedHosts;

    private SimConfig(Builder b) {
        map = b.map != null ? b.map : WarehouseMap.paper();
        rules = b.rules;
        bindAddress = b.bindAddress;
        port = b.port;
        stepMillis = b.stepMillis;
        speed = b.speed;
        manualStep = b.manualStep;
        ioThreads = b.ioThreads;
        fleetFaults = b.fleetFaults;
        robotFaults = Map.copyOf(b.robotFaults);
        maxQueuedMissions = b.maxQueuedMissions;
        requestTimeoutMillis = b.requestTimeoutMillis;
        allowedHosts = Set.copyOf(b.allowedHosts);
    }

    public static Builder builder() {
        return new Builder();
    }

    public WarehouseMap map() {
        return map;
    }

    public SimRules rules() {
        return rules;
    }

    public String bindAddress() {
        return bindAddress;
    }

    public int port() {
        return port;
    }

    public int stepMillis() {
        return stepMillis;
    }

    public double speed() {
        return speed;
    }

    /** True when steps happen only on request ({@link RobotSim#step(int)} or {@code POST /admin/step}). */
    public boolean manualStep() {
        return manualStep;
    }

    /** Netty I/O threads; 0 means one per core. */
    public int ioThreads() {
        return ioThreads;
    }

    public FaultSettings fleetFaults() {
        return fleetFaults;
    }

    public Map<String, FaultSettings> robotFaults() {
        return robotFaults;
    }

    /** Missions a robot may have waiting (not counting its running one); one more is refused with 429. */
    public int maxQueuedMissions() {
        return maxQueuedMissions;
    }

    /** Time a request may take to arrive whole (headers and body) once its first bytes came; then 408. */
    public int requestTimeoutMillis() {
        return requestTimeoutMillis;
    }

    /**
     * Host names accepted in the {@code Host} header besides 127.0.0.1, localhost, [::1] and the bind address
     * (lower case; IPv6 addresses in brackets).
     */
    public Set<String> allowedHosts() {
        return allowedHosts;
    }

    /**
     * A host name as the {@code Host} header writes it: lower case, an IPv6 address in brackets.
     *
     * @throws IllegalArgumentException when it is no host name or address (for example it has a port or a path)
     */
    public static String hostName(String name) {
        String n = Objects.requireNonNull(name, "host name").strip().toLowerCase(Locale.ROOT);
        String bare = n.startsWith("[") && n.endsWith("]") ? n.substring(1, n.length() - 1) : n;
        if (bare.contains(":") && bare.matches("[0-9a-f:.]+(%[a-z0-9]+)?")) {
            return "[" + bare + "]"; // an IPv6 address
        }
        if (!HOST_NAME.matcher(n).matches()) {
            throw new IllegalArgumentException("'" + name + "' is not a host name (give a name or an address, "
                    + "without scheme, port or path, e.g. robots.example or 192.168.1.20)");
        }
        return n;
    }

    /** Wall-clock time between two automatic steps, in nanoseconds. */
    public long stepPeriodNanos() {
        return Math.max(1L, Math.round(stepMillis * 1_000_000L / speed));
    }

    /** Fluent builder; every setter checks its argument. */
    public static final class Builder {
        private WarehouseMap map;
        private SimRules rules = SimRules.DEFAULT;
        private String bindAddress = "127.0.0.1";
        private int port;
        private int stepMillis = DEFAULT_STEP_MILLIS;
        private double speed = 1.0;
        private boolean manualStep;
        private int ioThreads;
        private FaultSettings fleetFaults = FaultSettings.NONE;
        private final Map<String, FaultSettings> robotFaults = new LinkedHashMap<>();
        private int maxQueuedMissions = DEFAULT_MAX_QUEUED_MISSIONS;
        private int requestTimeoutMillis = DEFAULT_REQUEST_TIMEOUT_MILLIS;
        private final Set<String> allowedHosts = new LinkedHashSet<>();

        public Builder map(WarehouseMap value) {
            map = Objects.requireNonNull(value, "map");
            return this;
        }

        public Builder rules(SimRules value) {
            rules = Objects.requireNonNull(value, "rules");
            return this;
        }

        public Builder seed(long value) {
            rules = rules.withSeed(value);
            return this;
        }

        /** An address or host name to listen on (127.0.0.1). */
        public Builder bindAddress(String value) {
            hostName(value); // refuses what is no name or address
            bindAddress = value;
            return this;
        }

        /** 0 picks a free port. */
        public Builder port(int value) {
            if (value < 0 || value > 65535) {
                throw new IllegalArgumentException("port must be 0..65535, was " + value);
            }
            port = value;
            return this;
        }

        public Builder stepMillis(int value) {
            if (value < 1) {
                throw new IllegalArgumentException("stepMillis must be >= 1, was " + value);
            }
            stepMillis = value;
            return this;
        }

        public Builder speed(double value) {
            if (!(value > 0 && value <= 10_000)) {
                throw new IllegalArgumentException("speed must be > 0 and <= 10000, was " + value);
            }
            speed = value;
            return this;
        }

        public Builder manualStep(boolean value) {
            manualStep = value;
            return this;
        }

        public Builder ioThreads(int value) {
            if (value < 0) {
                throw new IllegalArgumentException("ioThreads must be >= 0, was " + value);
            }
            ioThreads = value;
            return this;
        }

        public Builder fleetFaults(FaultSettings value) {
            fleetFaults = Objects.requireNonNull(value, "fleetFaults");
            return this;
        }

        public Builder robotFaults(String robotId, FaultSettings value) {
            robotFaults.put(Objects.requireNonNull(robotId, "robotId"), Objects.requireNonNull(value, "faults"));
            return this;
        }

        /** Missions a robot may have waiting (1..1,000,000; default 64). */
        public Builder maxQueuedMissions(int value) {
            if (value < 1 || value > 1_000_000) {
                throw new IllegalArgumentException("maxQueuedMissions must be 1..1000000, was " + value);
            }
            maxQueuedMissions = value;
            return this;
        }

        /** Time a request may take to arrive whole, in ms (100..3,600,000; default 10,000). */
        public Builder requestTimeoutMillis(int value) {
            if (value < 100 || value > 3_600_000) {
                throw new IllegalArgumentException("requestTimeoutMillis must be 100..3600000, was " + value);
            }
            requestTimeoutMillis = value;
            return this;
        }

        /** Also accepts this name in the {@code Host} header (and in {@code Origin}); see {@link #hostName}. */
        public Builder allowHost(String name) {
            allowedHosts.add(hostName(name));
            return this;
        }

        public SimConfig build() {
            return new SimConfig(this);
        }
    }
}
