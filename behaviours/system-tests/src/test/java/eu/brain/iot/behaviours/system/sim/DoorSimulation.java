package eu.brain.iot.behaviours.system.sim;

import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/**
 * Simulation of the extern function of {@code behaviours/door/src/main/bip/Door.bip}: {@code open} commands the
 * physical door, which the environment model ({@code Doorway} in WarehouseEnvironment.bip) is; nothing to do here.
 */
public final class DoorSimulation implements SimulationExterns {

    /** The extern functions of Door.bip this class simulates. */
    public static final Set<String> FUNCTIONS = Set.of("open");

    @Override
    public Object call(String name, List<String> paramTypes, String resultType, Object[] args, TraceRandom random) {
        if (name.equals("open")) {
            return null;
        }
        throw WarehouseSimulation.unknown(name, paramTypes, getClass());
    }
}
