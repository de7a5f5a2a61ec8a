package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * Who commanded a robot last, and when; how many times its commanding node changed, and the change with the
 * shortest wall time between the two nodes' commands (kept here whatever the bounded log of changes dropped).
 * Immutable.
 *
 * @param node            the node named by the last command ({@code X-Brain-Node}), {@code "unknown"} without it
 * @param warehouseMs     warehouse time of the last command
 * @param wallMillis      wall time (epoch ms) of the last command
 * @param commands        commands received for the robot
 * @param handovers       times the commanding node changed
 * @param closestHandover the change with the shortest wall gap, or null when there was none
 */
@JsonPropertyOrder({"node", "warehouseMs", "wallMillis", "commands", "handovers", "closestHandover"})
public record RobotCommander(String node, long warehouseMs, long wallMillis, long commands, long handovers,
                             OwnershipChange closestHandover) {
}
