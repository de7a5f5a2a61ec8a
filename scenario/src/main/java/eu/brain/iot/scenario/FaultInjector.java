package eu.brain.iot.scenario;

import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.fault.FaultSettings;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Injects the planned faults when their warehouse time comes: a robot offline (and back) through robot-sim's fault
 * API; a behaviour bundle stopped through a node's Gogo shell, as an operator would ({@code lb -s}, then
 * {@code stop <id>}); a fabric node's JVM killed outright. Keeps a log of what it did, and can tell whether a
 * stopped behaviour is active again.
 * <p>
 * Threads: confined to the runner's loop thread.
 */
final class FaultInjector {
    private static final Duration SHELL_TIMEOUT = Duration.ofSeconds(20);

    private final RobotSim sim;
    private final NodeGroup nodes;
    private final List<Pending> pending = new ArrayList<>();
    private final List<String> log = new ArrayList<>();
    private final List<String> stoppedBundles = new ArrayList<>();

    /** A fault action due at a warehouse time. */
    private record Pending(long atMillis, PlannedFault fault, boolean start) {
    }

    /** The warehouse time of the look being applied. */
    private long nowMillis;

    FaultInjector(RobotSim sim, NodeGroup nodes, List<PlannedFault> faults) {
        this.sim = sim;
        this.nodes = nodes;
        for (PlannedFault f : faults) {
            pending.add(new Pending(f.atMillis(), f, true));
            if (f.endsAtMillis() > f.atMillis()) {
                pending.add(new Pending(f.endsAtMillis(), f, false));
            }
        }
        pending.sort(Comparator.comparingLong(Pending::atMillis));
    }

    /** Applies every action due at or before this warehouse time; returns what was done, for the terminal. */
    List<String> apply(long warehouseMillis) {
        List<String> done = new ArrayList<>();
        nowMillis = warehouseMillis;
        while (!pending.isEmpty() && pending.get(0).atMillis() <= warehouseMillis) {
            Pending p = pending.remove(0);
            String what = p.fault().inject(this, p.start());
            String line = "[" + WarehouseTime.format(warehouseMillis) + "] fault: " + what;
            log.add(line);
            done.add(line);
        }
        return done;
    }

    /**
     * Ends every fault still going on (a robot still offline comes back), so that the end state is judged fairly.
     *
     * @return the faults that never started (due after the run ended), as a person reads them
     */
    List<String> clear() {
        List<String> notDone = new ArrayList<>();
        for (Pending p : pending) {
            if (!p.start() && p.fault().endsWithTheRun()) {
                p.fault().inject(this, false);
            } else {
                notDone.add(p.fault().describe());
            }
        }
        pending.clear();
        return notDone;
    }

    String offline(PlannedFault.Offline off, boolean on) {
        int robot = sim.robotIds().indexOf(off.robot());
        FaultSettings now = sim.faults().effective(robot);
        sim.faults().setOwn(robot, new FaultSettings(now.latencyMs(), now.errorRate(), now.malformedRate(),
                now.dropRate(), on));
        return off.robot() + (on ? " goes offline (robot-sim answers 503, the robot stands still) for "
                + WarehouseTime.format(off.forMillis()) : " is back online");
    }

    String stopBehaviour(PlannedFault.StopBehaviour stop) {
        String name = stop.symbolicName();
        try {
            NodeGroup.Found found = nodes.find(name);
            if (found == null) {
                return "no bundle " + name + " is installed in " + (nodes.fabricOfNodes() ? "any live node"
                        : "the node") + ": nothing to stop";
            }
            Bundles.Bundle b = found.bundle();
            List<String> answer = found.member().node.shell("stop " + b.id(), SHELL_TIMEOUT).stream()
                    .filter(l -> !l.isBlank()).toList();
            stoppedBundles.add(name);
            return "stopped " + name + " (bundle " + b.id() + ", was " + b.state() + ") in "
                    + (nodes.fabricOfNodes() ? found.member().spec.name() + "'s shell" : "the node's shell")
                    + (answer.isEmpty() ? "" : ": " + String.join(" ", answer));
        } catch (java.io.IOException e) {
            return "could not stop " + name + ": " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted while stopping " + name;
        }
    }

    /** Starts a node killed earlier again ({@link NodeGroup#restart}). */
    String restartNode(PlannedFault.KillNode kill) {
        try {
            return nodes.restart(kill.node(), nowMillis);
        } catch (java.io.IOException e) {
            return "could not start " + kill.node() + " again: " + e.getMessage();
        }
    }

    /** Kills a fabric node's JVM outright (SIGKILL: {@link NodeGroup#kill}). */
    String killNode(PlannedFault.KillNode kill) {
        try {
            return nodes.kill(kill.node(), nowMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted while killing " + kill.node();
        }
    }

    /** The bundle with that symbolic name in the live nodes (an active one first), or null. */
    Bundles.Bundle bundle(String symbolicName) throws java.io.IOException, InterruptedException {
        NodeGroup.Found found = nodes.find(symbolicName);
        return found == null ? null : found.bundle();
    }

    /** Bundles this run stopped (symbolic names). */
    List<String> stoppedBundles() {
        return List.copyOf(stoppedBundles);
    }

    List<String> log() {
        return List.copyOf(log);
    }
}
