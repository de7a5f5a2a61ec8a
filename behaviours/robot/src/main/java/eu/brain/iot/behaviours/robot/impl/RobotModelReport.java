package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * A robot's model instance as the node that hosts it sees it ({@link RobotModelHost}): its places and data after the
 * transitions it took, and the effects those asked of the fleet ({@link ModelStep}s), for the instance that drives
 * the fleet ({@link RobotBinding}).
 */
public class RobotModelReport extends BrainIoTEvent {

    /** The node that hosts the instance (its edge owns the robot). */
    public String node;
    /** The robot. */
    public String robot;
    /** The coordinator of the last input fired ({@link RobotModelInput#coordinator}), or null for none yet. */
    public String coordinator;
    /** The last input fired ({@link RobotModelInput#seq}), or -1 for none. */
    public long seq = -1;
    /** The instance's marked places; empty while its group is not created (the model then reads START). */
    public List<String> places = new ArrayList<>();
    /** The instance's data, {@code name=value} pairs separated by spaces, sorted by name. */
    public String data = "";
    /** The extern functions' effects since the last report, in order ({@link ModelStep#text}). */
    public List<String> steps = new ArrayList<>();
}
