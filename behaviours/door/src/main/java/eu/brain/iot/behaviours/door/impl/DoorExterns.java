package eu.brain.iot.behaviours.door.impl;

import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.service.component.annotations.Component;

import eu.brain.iot.behaviours.door.DoorBehaviorExterns;

/** The door model's extern function: command the automatic door to open (counted, and logged). */
@Component(service = DoorBehaviorExterns.class)
public class DoorExterns implements DoorBehaviorExterns {

    private static final System.Logger LOG = System.getLogger(DoorExterns.class.getName());

    private final AtomicInteger openings = new AtomicInteger();

    @Override
    public void open(int requests) {
        openings.incrementAndGet();
        LOG.log(System.Logger.Level.INFO, "door opens (request {0})", requests);
    }

    /** @return how many times the door was commanded open */
    public int openings() {
        return openings.get();
    }
}
