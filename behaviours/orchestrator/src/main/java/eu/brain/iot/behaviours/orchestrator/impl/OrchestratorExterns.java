package eu.brain.iot.behaviours.orchestrator.impl;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.behaviours.orchestrator.OrchestratorBehaviorExterns;
import eu.brain.iot.behaviours.warehouse.ModelInstance;

/**
 * The orchestrator model's collision resolution: resolvedPositionK for the model's RobotK of the group named by the
 * last {@link #bipInstance} on the calling thread (RobotK of group gN is the fleet's robot{@code 3(N-1)+K},
 * {@link ModelInstance}), by the rule of {@link CollisionGeometry}. A position 0 is a robot not in the interaction (the subset
 * rendezvous of Warehouse.bip): it stays 0. Without an edge (the model on a bus alone) every robot concerned keeps
 * its position (waits, then goes on). Thread-safe: the geometry reference is volatile,
 * the geometry thread-safe, the instance kept per thread.
 */
@Component(service = OrchestratorBehaviorExterns.class)
public class OrchestratorExterns implements OrchestratorBehaviorExterns {

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    volatile CollisionGeometry geometry;

    private final ModelInstance instance = new ModelInstance();

    @Override
    public void bipInstance(String group, String component) {
        instance.set(group, component);
    }

    private double resolve(int k, double position) {
        CollisionGeometry g = geometry;
        if (position == 0 || g == null) {
            return position;
        }
        return g.resolve(instance.robotId(k), position);
    }

    @Override
    public double resolvedPosition1(double position1) {
        return resolve(1, position1);
    }

    @Override
    public double resolvedPosition2(double position2) {
        return resolve(2, position2);
    }

    @Override
    public double resolvedPosition3(double position3) {
        return resolve(3, position3);
    }
}
