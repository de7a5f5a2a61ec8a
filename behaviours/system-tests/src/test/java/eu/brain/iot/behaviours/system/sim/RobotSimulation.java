package eu.brain.iot.behaviours.system.sim;

import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/**
 * Simulation of the extern functions of {@code behaviours/robot/src/main/bip/Robot.bip} for statistical model
 * checking. The robot's body is the environment model ({@code Motion} in WarehouseEnvironment.bip), so what the
 * deployed {@code RobotExterns} sends to the fleet is not repeated here: {@code getPosition} answers where every robot
 * starts (docked, as {@code RobotExterns} answers before any move), {@code liftCart} counts down like the deployed one
 * (without its log line, which thousands of traces would flood), {@code moveTo} and {@code placeCart} are the environment's business.
 * No state: the same answer for every trace.
 */
public final class RobotSimulation implements SimulationExterns {

    /** The extern functions of Robot.bip this class simulates. */
    public static final Set<String> FUNCTIONS = Set.of("getPosition", "liftCart", "moveTo", "placeCart");

    static final double IN_DOCKING = 1;

    @Override
    public Object call(String name, List<String> paramTypes, String resultType, Object[] args, TraceRandom random) {
        return switch (name) {
            case "getPosition" -> IN_DOCKING;
            case "liftCart" -> Math.max(0, (Integer) args[1] - 1);
            case "moveTo", "placeCart" -> null;
            default -> throw WarehouseSimulation.unknown(name, paramTypes, getClass());
        };
    }
}
