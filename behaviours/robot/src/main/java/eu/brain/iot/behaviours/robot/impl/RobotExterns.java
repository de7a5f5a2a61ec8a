package eu.brain.iot.behaviours.robot.impl;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.behaviours.robot.RobotBehaviorExterns;
import eu.brain.iot.behaviours.warehouse.Cell;

/**
 * The robot model's extern functions, acting on the fleet through {@link RobotFleet} (edge commands only).
 * Positions in the model are area codes (Warehouse.bip: inDocking = 1, inUnload = 2, inStorage = 3); the cells are
 * the errand table's. {@code moveTo(id, p)}: {@code p > 0} (an area code) means "go on with your errand";
 * {@code p < 0} is a cell the orchestrator chose for the robot to step aside to, encoded as
 * {@code -(1 + x + 1000 y)} ({@link #sideStep}); {@code p == 0} (not concerned) does nothing.
 * <p>
 * Without an edge (the model on a bus alone, as in the model-level tests) there is no {@link RobotFleet}: the
 * functions then only log, and {@code liftCart} counts down as the model expects.
 * Thread-safe: the fleet reference is volatile and the fleet is thread-safe.
 */
@Component(service = RobotBehaviorExterns.class)
public class RobotExterns implements RobotBehaviorExterns {

    static final double IN_DOCKING = 1;

    private static final System.Logger LOG = System.getLogger(RobotExterns.class.getName());

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    volatile RobotFleet fleet;

    /** The fleet's id of the model's robot {@code id} (group g1: Robot1..3 are robot1..3). */
    static String robot(int id) {
        return "robot" + id;
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
        return f == null ? IN_DOCKING : f.area(robot(robotId));
    }

    @Override
    public int liftCart(int robotId, int remaining) {
        int left = Math.max(0, remaining - 1);
        RobotFleet f = fleet;
        LOG.log(System.Logger.Level.INFO, "robot {0} lifts a cart (corkscrew); {1} cart(s) left", robotId, left);
        if (f != null) {
            f.lift(robot(robotId));
        }
        return left;
    }

    @Override
    public void moveTo(int robotId, double position) {
        RobotFleet f = fleet;
        Cell aside = sideStep(position);
        LOG.log(System.Logger.Level.INFO, "robot {0} moves to {1}", robotId,
                aside != null ? "the side cell " + aside : position);
        if (position == 0) {
            return;
        }
        if (f == null) {
            LOG.log(System.Logger.Level.WARNING, "robot {0}: no fleet service (no edge, or being replaced): not "
                    + "moved; the binding sends it on once it is back", robotId);
            return;
        }
        if (aside != null) {
            f.sideStep(robot(robotId), aside);
        } else {
            f.resume(robot(robotId), "its errand");
        }
    }

    @Override
    public void placeCart(int robotId) {
        RobotFleet f = fleet;
        LOG.log(System.Logger.Level.INFO, "robot {0} places its cart in storage", robotId);
        if (f != null) {
            f.place(robot(robotId));
        }
    }
}
