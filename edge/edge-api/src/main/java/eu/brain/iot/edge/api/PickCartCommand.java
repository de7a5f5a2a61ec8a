package eu.brain.iot.edge.api;

/** Lift the cart the robot stands under (queued after the robot's other missions). */
public class PickCartCommand extends EdgeCommand {
}
