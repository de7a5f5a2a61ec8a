package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.Dictionary;
import java.util.HashMap;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.Future;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;

import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.behaviours.robot.RobotSmartBehaviour;
import eu.brain.iot.behaviours.warehouse.BindingThread;
import eu.brain.iot.behaviours.warehouse.RobotNames;
import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * Hosts the model instances of the robots this node owns: a robot's instance runs on the node whose edge owns the
 * robot. The instance that drives the fleet ({@link RobotBinding}) sends each port event as a {@link RobotModelInput}
 * naming the robot's owner; the host takes the inputs naming its node (a smart behaviour registered with the filter
 * {@code (node=<its node>)}), fires each on its model ({@link RobotSmartBehaviour}) and answers with a
 * {@link RobotModelReport}: the instance's places and data after the transitions, and the effects they asked of the
 * fleet ({@link RobotExterns}' steps). It also reports, every look ({@code poll.period.ms} of warehouse time), each
 * owned robot whose instance changed through the orchestrator or the door (their connector events reach the model on
 * every node; only an instance waiting for one takes part), and every robot it owns once a second of wall time, so
 * that an instance that takes the fleet over learns them, and at once when another instance drives it; these only
 * once an instance is known to drive the fleet ({@link FleetLeadership#leaderId}: a node just started has not heard it
 * yet, and a report nobody takes would have the BMS look for a behaviour that does). A host ignores the inputs of
 * robots its node does not own (one handed over since the input was sent): the binding sends them again when no
 * report comes.
 * <p>
 * Threads: {@link #notify} (the bus's thread) hands every input to the host's own thread, which fires, reports and
 * owns this object's state; the model and the extern functions' steps are read together under the model's lock.
 */
@Component(service = {}, configurationPid = RobotConfig.PID, immediate = true)
@SmartBehaviourDefinition(consumed = RobotModelInput.class, author = RobotModelHost.AUTHOR, name = RobotModelHost.NAME,
        description = RobotModelHost.DESCRIPTION)
public final class RobotModelHost implements SmartBehaviour<RobotModelInput> {

    static final String AUTHOR = "BRAIN-IoT fabric";
    static final String NAME = "Robot model host";
    static final String DESCRIPTION = "Runs the robot model's instances of the robots this node owns";

    /** Wall time between two reports of every robot the node owns, changed or not. */
    static final long FULL_REPORT_NANOS = TimeUnit.SECONDS.toNanos(1);

    private static final System.Logger LOG = System.getLogger(RobotModelHost.class.getName());

    private final EventBus bus;
    private final DeviceOwnership ownership;
    /** Whether an instance drives the fleet: until one is known, reports made without an input have no taker. */
    private final FleetLeadership leadership;
    private final RobotSmartBehaviour model;
    private final RobotExterns externs;
    private final BindingThread thread;
    private final Future<?> looks;
    /** This host as a smart behaviour taking its node's inputs; null without a framework (the unit tests). */
    private final ServiceRegistration<?> registration;

    // the host's thread only
    /** Per robot, the last report sent (its content, without steps). */
    private final Map<String, Reported> reported = new HashMap<>();
    /** Per robot, the last input fired. */
    private final Map<String, Fired> fired = new HashMap<>();
    private long lastFull;
    /** The instance that drives the fleet at the last look: one that takes over has every robot reported at once. */
    private String lastLeader;

    private record Fired(String coordinator, long seq) {
    }

    private record Reported(Fired fired, List<String> places, String data) {
    }

    @Activate
    public RobotModelHost(@Reference EventBus bus, @Reference DeviceOwnership ownership,
            @Reference FleetLeadership leadership,
            @Reference(target = "(component.name=eu.brain.iot.behaviours.robot.RobotSmartBehaviour)")
            SmartBehaviour<?> model, @Reference RobotExterns externs, RobotConfig config, BundleContext context) {
        this.bus = bus;
        this.ownership = ownership;
        this.leadership = leadership;
        this.model = (RobotSmartBehaviour) model;
        this.externs = externs;
        this.thread = new BindingThread("robot-model-host", config.speed(), config.poll_period_ms());
        this.lastFull = System.nanoTime() - FULL_REPORT_NANOS;
        this.looks = thread.start(this::safeLook);
        this.registration = context == null ? null
                : context.registerService(SmartBehaviour.class, this, properties(ownership.nodeName()));
    }

    /**
     * @return the service properties of a smart behaviour that takes the inputs naming this node (its declaration
     *         above holds the same, but for the filter: the node's name is known only once the component runs)
     */
    static Dictionary<String, Object> properties(String node) {
        Hashtable<String, Object> p = new Hashtable<>();
        p.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { RobotModelInput.class.getName() });
        p.put(SmartBehaviourNamespace.FILTER_PROPERTY, "(node=" + escaped(node) + ")");
        p.put(SmartBehaviourNamespace.PROPERTY_PREFIX + SmartBehaviourNamespace.AUTHOR, AUTHOR);
        p.put(SmartBehaviourNamespace.PROPERTY_PREFIX + SmartBehaviourNamespace.NAME, NAME);
        p.put(SmartBehaviourNamespace.PROPERTY_PREFIX + SmartBehaviourNamespace.DESCRIPTION, DESCRIPTION);
        return p;
    }

    /** @return the value with the characters an LDAP filter's value escapes (RFC 4515) escaped */
    static String escaped(String value) {
        StringBuilder b = new StringBuilder();
        for (char c : value.toCharArray()) {
            switch (c) {
                case '\\', '*', '(', ')', '\0' -> b.append('\\').append(String.format("%02x", (int) c));
                default -> b.append(c);
            }
        }
        return b.toString();
    }

    @Deactivate
    void deactivate() {
        if (registration != null) {
            registration.unregister();
        }
        looks.cancel(false);
        thread.close();
    }

    @Override
    public void notify(RobotModelInput input) {
        try {
            thread.execute(() -> fire(input));
        } catch (RejectedExecutionException e) {
            // the host is going away: the binding sends the input again to the robot's next host
        }
    }

    private void fire(RobotModelInput input) {
        String robot = input.robotId;
        if (robot == null || RobotNames.number(robot) < 1 || !ownership.owns(robot)) {
            return; // a robot this node no longer owns (the input crossed its hand-over)
        }
        ModelPort port;
        try {
            port = ModelPort.valueOf(String.valueOf(input.port));
        } catch (IllegalArgumentException e) {
            LOG.log(System.Logger.Level.WARNING, "robot model host: {0} for {1} is not a port of the robot model"
                    + " ({2}): ignored", input.port, robot, List.of(ModelPort.values()));
            return;
        }
        try {
            model.notify(port.event(robot, input.position, input.detect));
        } finally {
            fired.put(robot, new Fired(input.coordinator, input.seq));
            report(robot, true);
        }
    }

    private void safeLook() {
        try {
            long now = System.nanoTime();
            String leader = leadership.leaderId();
            boolean full = now - lastFull >= FULL_REPORT_NANOS || !Objects.equals(leader, lastLeader);
            lastLeader = leader;
            if (full) {
                lastFull = now;
            }
            for (String robot : leader != null ? ownership.owned() : Set.<String>of()) {
                if (RobotNames.number(robot) >= 1) {
                    report(robot, full);
                }
            }
            for (String robot : new ArrayList<>(reported.keySet())) {
                if (!ownership.owns(robot)) {
                    reported.remove(robot); // reported again at once should it come back
                    fired.remove(robot);
                    externs.takeSteps(robot); // asked by an instance this node no longer drives
                }
            }
        } catch (RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "robot model host: a look at the model failed", e);
        }
    }

    /** Reports the robot's instance if it changed, took steps, or {@code always}. */
    private void report(String robot, boolean always) {
        int k = RobotNames.number(robot);
        List<String> places;
        Map<String, Object> data;
        List<ModelStep> steps;
        synchronized (model) { // between two transitions: the steps a transition asked for go with its places
            places = model.placesOf(RobotNames.group(k), RobotNames.component(k));
            data = model.dataOf(RobotNames.group(k), RobotNames.component(k));
            steps = externs.takeSteps(robot);
        }
        Reported now = new Reported(fired.get(robot), places == null ? List.of() : List.copyOf(places), text(data));
        if (!always && steps.isEmpty() && now.equals(reported.get(robot))) {
            return;
        }
        reported.put(robot, now);
        RobotModelReport r = new RobotModelReport();
        r.node = ownership.nodeName();
        r.robot = robot;
        if (now.fired() != null) {
            r.coordinator = now.fired().coordinator();
            r.seq = now.fired().seq();
        }
        r.places = new ArrayList<>(now.places());
        r.data = now.data();
        steps.forEach(s -> r.steps.add(s.text()));
        bus.deliver(r);
    }

    /** @return the data as {@code name=value} pairs, sorted by name; empty for none */
    static String text(Map<String, Object> data) {
        if (data == null) {
            return "";
        }
        StringBuilder b = new StringBuilder();
        new TreeMap<>(data).forEach((name, value) -> b.append(b.length() == 0 ? "" : " ").append(name).append('=')
                .append(value));
        return b.toString();
    }
}
