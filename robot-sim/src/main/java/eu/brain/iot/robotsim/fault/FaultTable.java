package eu.brain.iot.robotsim.fault;

import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReferenceArray;

/**
 * Fault settings for the fleet and per robot, changed at run time by the admin endpoints and read by every HTTP
 * thread and the step thread. Thread-safe without locks: settings are immutable records published through
 * volatile/atomic references; a robot's own settings, when present, replace the fleet-wide ones for it.
 */
public final class FaultTable {
    private final AtomicReferenceArray<FaultSettings> perRobot;
    private final AtomicLongArray requests;
    private volatile FaultSettings fleet = FaultSettings.NONE;

    public FaultTable(int robots) {
        perRobot = new AtomicReferenceArray<>(robots);
        requests = new AtomicLongArray(robots);
    }

    public FaultSettings fleet() {
        return fleet;
    }

    public void setFleet(FaultSettings settings) {
        fleet = settings;
    }

    /** The robot's own settings, or null when it follows the fleet-wide ones. */
    public FaultSettings own(int robot) {
        return perRobot.get(robot);
    }

    /** Gives a robot its own settings; null makes it follow the fleet-wide ones again. */
    public void setOwn(int robot, FaultSettings settings) {
        perRobot.set(robot, settings);
    }

    /** Clears every fault, fleet-wide and per robot. */
    public void clear() {
        fleet = FaultSettings.NONE;
        for (int i = 0; i < perRobot.length(); i++) {
            perRobot.set(i, null);
        }
    }

    public FaultSettings effective(int robot) {
        FaultSettings own = perRobot.get(robot);
        return own != null ? own : fleet;
    }

    public boolean offline(int robot) {
        return effective(robot).offline();
    }

    /** Decides the fate of the next request to a robot (counts it). */
    public FaultAction next(int robot, FaultSettings f) {
        if (f.offline()) {
            return FaultAction.OFFLINE;
        }
        if (f.dropRate() == 0 && f.errorRate() == 0 && f.malformedRate() == 0) {
            return FaultAction.NONE;
        }
        long n = requests.getAndIncrement(robot);
        if (hits(f.dropRate(), n)) {
            return FaultAction.DROP;
        }
        if (hits(f.errorRate(), n)) {
            return FaultAction.ERROR_500;
        }
        if (hits(f.malformedRate(), n)) {
            return FaultAction.MALFORMED;
        }
        return FaultAction.NONE;
    }

    /** True for request n when the running count of hits at this rate goes up: exact, deterministic spacing. */
    static boolean hits(double rate, long n) {
        return rate > 0 && Math.floor((n + 1) * rate) > Math.floor(n * rate);
    }
}
