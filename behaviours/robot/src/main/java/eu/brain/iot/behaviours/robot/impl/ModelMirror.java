package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * The robots' model instances as the binding knows them: each as its host last reported it ({@link RobotModelHost},
 * on the robot's owner), and the input sent to it that no report has answered yet, during which the binding leaves
 * the robot alone (the instance may be between a transition and the report of its steps). An input not answered
 * within {@code lostAfterNanos} (its host died, or let the robot go) is given up, and the binding sends what the
 * robot's state calls for again. Threads: the binding's thread only.
 */
final class ModelMirror {

    private static final System.Logger LOG = System.getLogger(ModelMirror.class.getName());

    /** A robot's model instance: its host's node, its marked places (empty: not created yet), its data. */
    record Instance(String node, List<String> places, Map<String, Object> data) {
    }

    private record Sent(long seq, long atNanos) {
    }

    /**
     * Wall time from this mirror's start during which a robot whose instance no host has reported is left alone: its
     * host reports it within a second once it knows an instance drives the fleet ({@link RobotModelHost}). After it,
     * such a robot's instance is taken as in START: its node may have no host yet, which the first input has
     * installed.
     */
    static final long FIRST_REPORTS_NANOS = TimeUnit.MILLISECONDS.toNanos(1_500);

    private final String coordinator;
    private final long lostAfterNanos;
    private final long startedNanos;
    private long seq;
    private final Map<String, Instance> instances = new HashMap<>();
    private final Map<String, Sent> sent = new HashMap<>();

    /**
     * @param coordinator this binding's instance id, which its inputs carry and the reports echo
     * @param lostAfterNanos wall time after which an input without a report is given up
     */
    ModelMirror(String coordinator, long lostAfterNanos, long startedNanos) {
        this.coordinator = coordinator;
        this.lostAfterNanos = lostAfterNanos;
        this.startedNanos = startedNanos;
    }

    /** @return whether the robot's instance is not reported yet and may still be, being early days for this mirror */
    boolean reportDue(String robot, long nowNanos) {
        return !instances.containsKey(robot) && nowNanos - startedNanos < FIRST_REPORTS_NANOS;
    }

    /** @return the input firing the port of the robot's instance on its owner, recorded as awaiting its report */
    RobotModelInput input(String robot, String node, ModelPort port, double position, int detect, long nowNanos) {
        RobotModelInput in = new RobotModelInput();
        in.coordinator = coordinator;
        in.node = node;
        in.robotId = robot;
        in.seq = ++seq;
        in.port = port.name();
        in.position = position;
        in.detect = detect;
        sent.put(robot, new Sent(in.seq, nowNanos));
        return in;
    }

    /**
     * Takes a host's report.
     *
     * @return the steps the instance's transitions asked of the fleet, in order
     */
    List<ModelStep> reported(RobotModelReport r) {
        if (r.robot == null || r.node == null) {
            return List.of();
        }
        Instance before = instances.put(r.robot, new Instance(r.node,
                r.places == null ? List.of() : List.copyOf(r.places), data(r.data)));
        Sent s = sent.get(r.robot);
        boolean answered = coordinator.equals(r.coordinator) && s != null && r.seq >= s.seq();
        if (answered || before != null && !before.node().equals(r.node)) {
            sent.remove(r.robot); // answered, or hosted on another node now: what went to the one before is lost
        }
        List<ModelStep> steps = new ArrayList<>();
        for (String text : r.steps == null ? List.<String>of() : r.steps) {
            ModelStep.parse(text).ifPresentOrElse(steps::add, () -> LOG.log(System.Logger.Level.WARNING,
                    "robot model report of {0} from node {1}: \"{2}\" is not a step: ignored", r.robot, r.node, text));
        }
        return steps;
    }

    /** @return whether an input to the robot's instance awaits its report (given up after the time allowed) */
    boolean awaiting(String robot, long nowNanos) {
        Sent s = sent.get(robot);
        if (s != null && nowNanos - s.atNanos() >= lostAfterNanos) {
            LOG.log(System.Logger.Level.INFO, "{0}: no report of its model instance for {1} ms after input {2}: "
                    + "given up (sent again if still called for)", robot, (nowNanos - s.atNanos()) / 1_000_000,
                    s.seq());
            sent.remove(robot);
            return false;
        }
        return s != null;
    }

    /** @return the robot's instance as last reported, if it was */
    Optional<Instance> of(String robot) {
        return Optional.ofNullable(instances.get(robot));
    }

    /**
     * The robot appeared on the node that polls it now: an input still awaiting its report went to the host before,
     * and is not awaited any more (its new host reports the instance it has once it owns the robot).
     */
    void handedOver(String robot) {
        sent.remove(robot);
    }

    /** @return a report's data as values: booleans, whole numbers (Long), other numbers (Double), else text */
    static Map<String, Object> data(String text) {
        Map<String, Object> data = new LinkedHashMap<>();
        if (text == null || text.isBlank()) {
            return data;
        }
        for (String pair : text.trim().split(" ")) {
            int eq = pair.indexOf('=');
            if (eq > 0) {
                data.put(pair.substring(0, eq), value(pair.substring(eq + 1)));
            }
        }
        return data;
    }

    private static Object value(String v) {
        if ("true".equals(v) || "false".equals(v)) {
            return Boolean.valueOf(v);
        }
        try {
            return Long.valueOf(v);
        } catch (NumberFormatException notWhole) {
            try {
                return Double.valueOf(v);
            } catch (NumberFormatException notANumber) {
                return v;
            }
        }
    }
}
