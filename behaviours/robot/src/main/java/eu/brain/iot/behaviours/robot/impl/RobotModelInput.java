package eu.brain.iot.behaviours.robot.impl;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A port event of the robot model for the node that hosts the robot's model instance ({@link RobotModelHost}): the
 * instance that drives the fleet publishes it ({@link RobotBinding}) for the robot's owner, whose host (it takes the
 * inputs naming its node) fires the port on its model and answers with a {@link RobotModelReport}.
 */
public class RobotModelInput extends BrainIoTEvent {

    /** The robot behaviour instance that drives the fleet ({@link FleetLeadership}'s instance id). */
    public String coordinator;
    /** The node that owns the robot, as the coordinator's device model shows it: its host fires the port. */
    public String node;
    /**
     * The robot, e.g. {@code robot4}. Named as the edge's events name it, so that an input for a node without a host
     * has the robot behaviour installed on the robot's owner (federation/README.md, "The rule").
     */
    public String robotId;
    /** Increases with every input the coordinator sends; the host's report names the last it fired. */
    public long seq;
    /** The port, a {@link ModelPort} name. */
    public String port;
    /** The port event's data: the robot's area code. */
    public double position;
    /** The port event's data: what the robot detects (Warehouse.bip's codes; 0 for nothing). */
    public int detect;
}
