package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.behaviours.robot.RobotBehaviorExterns;
import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.ModelInstance;
import eu.brain.iot.behaviours.warehouse.RobotState;
import eu.brain.iot.edge.model.api.DeviceModel;

/**
 * The robot model's extern functions. They read the robot in this node's device model and leave what they ask of the
 * fleet as {@link ModelStep}s, which the node's {@link RobotModelHost} reports to the instance that drives the fleet.
 * Positions in the model are area codes (Warehouse.bip: inDocking = 1, inUnload = 2, inStorage = 3); the cells are
 * the errand table's. {@code moveTo(id, p)}: {@code p > 0} (an area code) means "go on with your errand";
 * {@code p < 0} is a cell the orchestrator chose for the robot to step aside to, encoded as
 * {@code -(1 + x + 1000 y)} ({@link #sideStep}); {@code p == 0} (not concerned) does nothing.
 * <p>
 * {@link #withoutFleet()} is the model on a bus alone (the model-level tests): no device model, no steps kept, a move
 * only says what it would do.
 * The functions act for the robot of the instance named by the last {@link #bipInstance} on the calling thread:
 * {@code Robot2} of group {@code g4} is robot11 ({@link ModelInstance}).
 * Thread-safe: the device model reference is volatile, the instance is kept per thread, the steps are per robot in a
 * concurrent map, each robot's list under its own lock.
 */
@Component(service = { RobotBehaviorExterns.class, RobotExterns.class })
public class RobotExterns implements RobotBehaviorExterns {

    static final double IN_DOCKING = 1;
    /** Steps kept per robot until its host reports them; beyond, the oldest are dropped (a host that stopped). */
    static final int MAX_STEPS = 64;

    private static final System.Logger LOG = System.getLogger(RobotExterns.class.getName());

    /** This node's device model as the fleet's view, or null without one. */
    private volatile Devices devices;

    private record Devices(DeviceModel model, FleetView view) {
    }

    private final ModelInstance instance = new ModelInstance();
    /** Whether steps are kept for a host: not for the model alone. */
    private final boolean keepSteps;
    private final Map<String, List<ModelStep>> steps = new ConcurrentHashMap<>();

    /** The component on a node: its steps go to the fleet through the node's host. */
    public RobotExterns() {
        this(true);
    }

    private RobotExterns(boolean keepSteps) {
        this.keepSteps = keepSteps;
    }

    /** The model on a bus alone, with no fleet by design: moves are only logged as what they would do. */
    public static RobotExterns withoutFleet() {
        return new RobotExterns(false);
    }

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    void bindDevices(DeviceModel model) {
        devices = new Devices(model, new FleetView(model));
    }

    void unbindDevices(DeviceModel model) {
        Devices d = devices;
        if (d != null && d.model() == model) { // a greedy replacement binds the new one first
            devices = null;
        }
    }

    /** @return the robot as this node's device model shows it, if it does */
    private Optional<RobotState> seen(String robot) {
        Devices d = devices;
        return d == null ? Optional.empty() : d.view().robot(robot);
    }

    @Override
    public void bipInstance(String group, String component) {
        instance.set(group, component);
    }

    /** The fleet's id of the model's robot {@code id} of the current instance's group. */
    String robot(int id) {
        return instance.robotId(id);
    }

    /** @return the steps asked for the robot since the last call, in order */
    List<ModelStep> takeSteps(String robot) {
        List<ModelStep> asked = steps.remove(robot);
        if (asked == null) {
            return List.of();
        }
        synchronized (asked) {
            return List.copyOf(asked);
        }
    }

    private void step(String robot, ModelStep step) {
        if (!keepSteps) {
            return;
        }
        List<ModelStep> asked = steps.computeIfAbsent(robot, r -> new ArrayList<>());
        synchronized (asked) {
            if (asked.size() >= MAX_STEPS) {
                asked.remove(0);
            }
            asked.add(step);
        }
    }

    /** @return the cell encoded by a negative resolved position, or {@code null} for a position that is not one */
    static Cell sideStep(double position) {
        if (position >= 0) {
            return null;
        }
        long v = Math.round(-position) - 1;
        return new Cell((int) (v % 1000), (int) (v / 1000));
    }

    /**
     * The robot's area code when it stands in docking, unload or storage; out on the floor elsewhere (the corridor, a
     * doorway) it counts as unload, so a robot the model first meets away from its dock starts {@code returning}
     * (Robot.bip's initial transition); docking when the device model does not show it.
     */
    @Override
    public double getPosition(int robotId) {
        return seen(robot(robotId)).map(s -> (double) (inModelArea(s.area()) ? s.area() : Grid.UNLOAD))
                .orElse(IN_DOCKING);
    }

    /** @return whether the area code is one the robot model knows: docking, unload or storage */
    static boolean inModelArea(int area) {
        return area == Grid.DOCKING || area == Grid.UNLOAD || area == Grid.STORAGE;
    }

    /**
     * Counts a lift against the robot's budget ({@code remaining}, Robot.bip's {@code cart}) only when the robot does
     * not carry a cart already: the model goes through CART again with the cart it carries when it is taken over
     * carrying one, or carries one back to storage whose place was lost ({@link Recovery}), and that cart was
     * counted when it was first lifted.
     */
    @Override
    public int liftCart(int robotId, int remaining) {
        String robot = robot(robotId);
        boolean again = seen(robot).map(RobotState::carrying).orElse(false);
        int left = again ? remaining : Math.max(0, remaining - 1);
        LOG.log(System.Logger.Level.INFO, again ? "{0} lifts the cart it carries again; {1} cart(s) left"
                : "{0} lifts a cart (corkscrew); {1} cart(s) left", robot, left);
        step(robot, ModelStep.LIFT);
        return left;
    }

    @Override
    public void moveTo(int robotId, double position) {
        String robot = robot(robotId);
        Cell aside = sideStep(position);
        LOG.log(System.Logger.Level.INFO, "{0} moves to {1}", robot, aside != null ? "the side cell " + aside
                : position);
        if (position == 0) {
            return;
        }
        step(robot, aside != null ? ModelStep.aside(aside) : ModelStep.MOVE_ON);
    }

    @Override
    public void placeCart(int robotId) {
        String robot = robot(robotId);
        LOG.log(System.Logger.Level.INFO, "{0} places its cart in storage", robot);
        step(robot, ModelStep.PLACE);
    }
}
