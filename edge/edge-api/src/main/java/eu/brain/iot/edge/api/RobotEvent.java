package eu.brain.iot.edge.api;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** Something the edge saw of one robot; consume this type to receive every robot event. */
public abstract class RobotEvent extends BrainIoTEvent {

    /** The robot's id in the fleet, for example {@code robot1}. */
    public String robotId;
}
