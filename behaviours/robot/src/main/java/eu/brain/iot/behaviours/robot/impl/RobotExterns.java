package eu.brain.iot.behaviours.robot.impl;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.behaviours.robot.RobotBehaviorExterns;
import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.ModelInstance;

/**
 * The robot model's extern functions, acting on the fleet through {@link RobotFleet} (edge commands only).
 * Positions in the model are area codes (Warehouse.bip: inDocking = 1, inUnload = 2, inStorage = 3); the cells are
 * the errand table's. {@code moveTo(id, p)}: {@code p > 0} (an area code) means "go on with your errand";
 * {@code p < 0} is a cell the orchestrator chose for the robot to step aside to, encoded as
 * {@code -(1 + x + 1000 y)} ({@link #sideStep}); {@code p == 0} (not concerned) does nothing.
 * <p>
 * Without an edge there is no {@link RobotFleet}: the functions then only log, and {@code liftCart} counts down as
 * the model expects. On a node (the component) a fleet is expected: a move it cannot make is a warning, once per
 * robot until the fleet is back. {@link #withoutFleet()} is the model on a bus alone (the model-level tests), where
 * no fleet is expected and a move only says what it would do.
 * The functions act for the robot of the instance named by the last {@link #bipInstance} on the calling thread:
 * {@code Robot2} of group {@code g4} is robot11 ({@link ModelInstance}).
 * Thread-safe: the fleet reference is volatile, what the functions do to the fleet runs on the fleet's own thread
 * ({@link RobotFleet#fromModel}), the instance is kept per thread, the robots warned about are a concurrent set.
 */
@Component(service = RobotBehaviorExterns.class)
public class RobotExterns implements RobotBehaviorExterns {

    static final double IN_DOCKING = 1;

    private static final System.Logger LOG = System.getLogger(RobotExterns.class.getName());

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    volatile RobotFleet fleet;

    private final ModelInstance instance = new ModelInstance();
    /** Whether a fleet is expected: a move without one is then a warning. */
    private final boolean fleetExpected;
    /** Robots not moved for want of a fleet since it was last there: warned about once each. */
    private final Set<String> unmoved = ConcurrentHashMap.newKeySet();

    /** The component on a node: it acts on the fleet through the edge. */
    public RobotExterns() {
        this(true);
    }

    private RobotExterns(boolean fleetExpected) {
        this.fleetExpected = fleetExpected;
    }

    /** The model on a bus alone, with no fleet by design: moves are only logged as what they would do. */
    public static RobotExterns withoutFleet() {
        return new RobotExterns(false);
    }

    @Override
    public void bipInstance(String group, String component) {
        instance.set(group, component);
    }

    /** The fleet's id of the model's robot {@code id} of the current instance's group. */
    String robot(int id) {
        return instance.robotId(id);
    }

    /** @return the cell encoded by a negative resolved position, or {@code null} for a position that is not one */
    static Cell sideStep(double position) {
        if (position >= 0) {
            return null;
        }
        long v = Math.round(-position) - 1;
        return new Cell((int) (v % 1000), (int) (v / 1000));
    }

    @Override
    public double getPosition(int robotId) {
        RobotFleet f = fleet;
        return f == null ? IN_DOCKING : f.position(robot(robotId));
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
        RobotFleet f = fleet;
        boolean again = f != null && f.carries(robot);
        int left = again ? remaining : Math.max(0, remaining - 1);
        LOG.log(System.Logger.Level.INFO, again ? "{0} lifts the cart it carries again; {1} cart(s) left"
                : "{0} lifts a cart (corkscrew); {1} cart(s) left", robot, left);
        if (f != null) {
            f.fromModel(robot(robotId), fleet -> fleet.lift(robot));
        }
        return left;
    }

    @Override
    public void moveTo(int robotId, double position) {
        RobotFleet f = fleet;
        Cell aside = sideStep(position);
        LOG.log(System.Logger.Level.INFO, "{0} moves to {1}", robot(robotId),
                aside != null ? "the side cell " + aside : position);
        if (position == 0) {
            return;
        }
        if (f == null) {
            if (fleetExpected && unmoved.add(robot(robotId))) {
                LOG.log(System.Logger.Level.WARNING, "{0}: no fleet service (no edge, or being replaced): not "
                        + "moved; the binding sends it on once it is back (further moves of {0} not made are not "
                        + "logged until then)", robot(robotId));
            }
            return;
        }
        if (!unmoved.isEmpty()) {
            unmoved.clear(); // the fleet is back: a new absence is warned about again
        }
        String robot = robot(robotId);
        if (aside != null) {
            f.fromModel(robot, fleet -> fleet.sideStep(robot, aside));
        } else {
            f.fromModel(robot, fleet -> fleet.resume(robot, "its errand"));
        }
    }

    @Override
    public void placeCart(int robotId) {
        RobotFleet f = fleet;
        LOG.log(System.Logger.Level.INFO, "{0} places its cart in storage", robot(robotId));
        if (f != null) {
            String robot = robot(robotId);
            f.fromModel(robot, fleet -> fleet.place(robot));
        }
    }
}
