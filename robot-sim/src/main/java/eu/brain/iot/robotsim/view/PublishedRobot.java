package eu.brain.iot.robotsim.view;

/** A robot view and its JSON, serialized once when the view changed; the bytes are never modified. */
public record PublishedRobot(RobotView view, byte[] json) {
}
