package eu.brain.iot.robotsim;

import eu.brain.iot.robotsim.fault.FaultSettings;
import eu.brain.iot.robotsim.world.SimRules;
import eu.brain.iot.robotsim.world.WarehouseMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

/**
 * How to start a simulator. Defaults: the paper's warehouse, seed 1, loopback address, an ephemeral port (the
 * command line uses 8090), one step every 500 ms at speed 1, fault-free.
 */
public final class SimConfig {
    public static final int DEFAULT_STEP_MILLIS = 500;

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

        public Builder bindAddress(String value) {
            bindAddress = Objects.requireNonNull(value, "bindAddress");
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

        public SimConfig build() {
            return new SimConfig(this);
        }
    }
}
