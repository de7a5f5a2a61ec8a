package eu.brain.iot.behaviours.robot.impl;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

import org.osgi.service.component.annotations.Component;

import eu.brain.iot.behaviours.robot.RobotBehaviorExterns;

/**
 * The robot model's extern functions. Positions are area codes (Warehouse.bip: inDocking = 1, ...): every robot
 * starts docked; {@code moveTo} records where the orchestrator sent a robot, {@code getPosition} answers from that
 * record, and {@code liftCart} counts down the carts left (the paper's {@code cart = liftCart()}).
 * The map is the only state; it is concurrent because a robot's instances may be hosted by several behaviours.
 */
@Component(service = RobotBehaviorExterns.class)
public class RobotExterns implements RobotBehaviorExterns {

    static final double IN_DOCKING = 1;

    private static final System.Logger LOG = System.getLogger(RobotExterns.class.getName());

    private final Map<Integer, Double> positions = new ConcurrentHashMap<>();

    @Override
    public double getPosition(int robotId) {
        return positions.getOrDefault(robotId, IN_DOCKING);
    }

    @Override
    public int liftCart(int robotId, int remaining) {
        int left = Math.max(0, remaining - 1);
        LOG.log(System.Logger.Level.INFO, "robot {0} lifts a cart (corkscrew); {1} cart(s) left", robotId, left);
        return left;
    }

    @Override
    public void moveTo(int robotId, double position) {
        positions.put(robotId, position);
        LOG.log(System.Logger.Level.INFO, "robot {0} moves to {1}", robotId, position);
    }
}
