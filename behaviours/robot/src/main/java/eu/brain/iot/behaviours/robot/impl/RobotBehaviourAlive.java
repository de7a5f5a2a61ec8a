package eu.brain.iot.behaviours.robot.impl;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A robot behaviour instance says it runs, every {@link FleetLeadership#BEAT_MILLIS}: every instance of the fabric
 * hears every other, and the oldest one alive drives the fleet ({@link FleetLeadership}).
 */
public class RobotBehaviourAlive extends BrainIoTEvent {

    /** The node the instance runs on (its edge's node name). */
    public String node;
    /** A random id of the instance, new at each start. */
    public String instance;
    /** When the instance started, epoch milliseconds. */
    public long startedMillis;
    /**
     * The instance stops (its bundle stops or its node shuts down): the others forget it at once, rather than one
     * alive period after its last beat, and the next one drives the fleet without the robots standing that long.
     */
    public boolean leaving;
    /**
     * The instance that drives the fleet: its errand table ({@link ErrandHandover}'s text), so that the one that takes
     * over continues the errands; null from an instance that stands by.
     */
    public String errands;
}
