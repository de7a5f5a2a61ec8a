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
}
