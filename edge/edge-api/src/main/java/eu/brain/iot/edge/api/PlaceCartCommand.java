package eu.brain.iot.edge.api;

/** Put down the cart the robot carries, where it stands (queued after the robot's other missions). */
public class PlaceCartCommand extends EdgeCommand {
}
