package eu.brain.iot.behaviours.door.impl;

import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.behaviours.door.DoorBehaviorExterns;
import eu.brain.iot.behaviours.warehouse.ModelInstance;

/**
 * The door model's extern function: open the door a robot of the instance's group waits at ({@link DoorControl}, an
 * edge command; the group is the one named by the last {@link #bipInstance} on the calling thread: each group's
 * {@code DoorInstance} opens the real door in front of its own robots).
 * Without an edge (the model on a bus alone, as in the model-level tests) it only counts and logs.
 * Thread-safe: the control reference is volatile, the counter atomic, the instance kept per thread.
 */
@Component(service = DoorBehaviorExterns.class)
public class DoorExterns implements DoorBehaviorExterns {

    private static final System.Logger LOG = System.getLogger(DoorExterns.class.getName());

    private final AtomicInteger openings = new AtomicInteger();

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    volatile DoorControl control;

    private final ModelInstance instance = new ModelInstance();

    @Override
    public void bipInstance(String group, String component) {
        instance.set(group, component);
    }

    @Override
    public void open(int requests) {
        openings.incrementAndGet();
        String group = instance.group();
        LOG.log(System.Logger.Level.INFO, "door of group {0} opens (request {1})", group, requests);
        DoorControl c = control;
        if (c != null) {
            c.openForWaitingRobot(group);
        }
    }

    /** @return how many times the door was commanded open */
    public int openings() {
        return openings.get();
    }
}
