package eu.brain.iot.robotsim.world;

/** Where a robot, cart or door stands when the world starts. */
public record Placement(String id, int x, int y) {
}
