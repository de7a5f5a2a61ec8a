package eu.brain.iot.behaviours.orchestrator.impl;

import org.osgi.service.component.annotations.Component;

import eu.brain.iot.behaviours.orchestrator.OrchestratorBehaviorExterns;

/**
 * The orchestrator model's collision resolution (the paper's resolvedPosition1..3, "AI algorithms" there): a fixed,
 * deterministic rule: robot 1 keeps its position and goes first, robots 2 and 3 fall back to the docking area
 * (area code 1) to clear the way. Stateless.
 */
@Component(service = OrchestratorBehaviorExterns.class)
public class OrchestratorExterns implements OrchestratorBehaviorExterns {

    static final double IN_DOCKING = 1;

    @Override
    public double resolvedPosition1(double position1) {
        return position1;
    }

    @Override
    public double resolvedPosition2(double position2) {
        return IN_DOCKING;
    }

    @Override
    public double resolvedPosition3(double position3) {
        return IN_DOCKING;
    }
}
