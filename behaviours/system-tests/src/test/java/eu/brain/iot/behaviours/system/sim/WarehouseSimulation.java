package eu.brain.iot.behaviours.system.sim;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.StochasticException;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/**
 * The extern functions of the warehouse's closed system in simulation ({@code set externs} of
 * src/main/bip/requirements.smc): each deployed model's functions go to the simulation written for that model. The
 * engine makes one instance per sampling thread; none of them keeps state.
 */
public final class WarehouseSimulation implements SimulationExterns {

    private final Map<String, SimulationExterns> byFunction = new HashMap<>();

    public WarehouseSimulation() {
        register(RobotSimulation.FUNCTIONS, new RobotSimulation());
        register(DoorSimulation.FUNCTIONS, new DoorSimulation());
        register(OrchestratorSimulation.FUNCTIONS, new OrchestratorSimulation());
    }

    private void register(Set<String> functions, SimulationExterns simulation) {
        functions.forEach(f -> byFunction.put(f, simulation));
    }

    /** @return whether some model's simulation answers this function */
    public boolean simulates(String name) {
        return byFunction.containsKey(name);
    }

    @Override
    public Object call(String name, List<String> paramTypes, String resultType, Object[] args, TraceRandom random) {
        SimulationExterns simulation = byFunction.get(name);
        if (simulation == null) {
            throw unknown(name, paramTypes, getClass());
        }
        return simulation.call(name, paramTypes, resultType, args, random);
    }

    static StochasticException unknown(String name, List<String> paramTypes, Class<?> where) {
        return new StochasticException("extern function " + name + paramTypes + " has no simulation in "
                + where.getSimpleName() + ": a model that declares a new extern function gets its simulation beside "
                + "the others in behaviours/system-tests/src/test/java/eu/brain/iot/behaviours/system/sim/");
    }
}
