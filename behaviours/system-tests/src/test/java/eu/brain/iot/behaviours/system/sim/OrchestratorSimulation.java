package eu.brain.iot.behaviours.system.sim;

import java.util.List;
import java.util.Set;

import eu.brain.iot.behaviours.orchestrator.impl.OrchestratorExterns;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/**
 * Simulation of the extern functions of {@code behaviours/orchestrator/src/main/bip/Orchestrator.bip}: the deployed
 * resolution rule without an edge ({@link OrchestratorExterns} with no device model: every robot concerned keeps its
 * position, and 0, not concerned, stays 0), a pure function. Which cell a robot steps aside to is the deployed
 * geometry's on a node (it reads the edge's device model); here the cells robots take are the environment's.
 */
public final class OrchestratorSimulation implements SimulationExterns {

    /** The extern functions of Orchestrator.bip this class simulates. */
    public static final Set<String> FUNCTIONS = Set.of("resolvedPosition1", "resolvedPosition2", "resolvedPosition3");

    private final OrchestratorExterns deployed = new OrchestratorExterns();

    @Override
    public Object call(String name, List<String> paramTypes, String resultType, Object[] args, TraceRandom random) {
        double position = args.length == 1 ? ((Number) args[0]).doubleValue() : 0;
        return switch (name) {
            case "resolvedPosition1" -> deployed.resolvedPosition1(position);
            case "resolvedPosition2" -> deployed.resolvedPosition2(position);
            case "resolvedPosition3" -> deployed.resolvedPosition3(position);
            default -> throw WarehouseSimulation.unknown(name, paramTypes, getClass());
        };
    }
}
