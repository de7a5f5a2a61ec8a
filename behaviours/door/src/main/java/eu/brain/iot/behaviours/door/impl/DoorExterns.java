package eu.brain.iot.behaviours.door.impl;

import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.behaviours.door.DoorBehaviorExterns;

/**
 * The door model's extern function: open the door a robot waits at ({@link DoorControl}, an edge command).
 * Without an edge (the model on a bus alone, as in the model-level tests) it only counts and logs.
 * Thread-safe: the control reference is volatile, the counter atomic.
 */
@Component(service = DoorBehaviorExterns.class)
public class DoorExterns implements DoorBehaviorExterns {

    private static final System.Logger LOG = System.getLogger(DoorExterns.class.getName());

    private final AtomicInteger openings = new AtomicInteger();

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    volatile DoorControl control;

    @Override
    public void open(int requests) {
        openings.incrementAndGet();
        LOG.log(System.Logger.Level.INFO, "door opens (request {0})", requests);
        DoorControl c = control;
        if (c != null) {
            c.openForWaitingRobot();
        }
    }

    /** @return how many times the door was commanded open */
    public int openings() {
        return openings.get();
    }
}
