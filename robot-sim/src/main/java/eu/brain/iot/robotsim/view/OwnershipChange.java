package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * A robot commanded by another node than the one that commanded it last: a hand-over of the robot between two
 * fabric nodes (or a command sent without naming a node, {@code "unknown"}). Immutable.
 *
 * @param robot               the robot
 * @param from                the node that commanded it before
 * @param to                  the node that commanded it now
 * @param fromLastWarehouseMs warehouse time of {@code from}'s last command to it
 * @param fromLastWallMillis  wall time (epoch ms) of {@code from}'s last command to it
 * @param warehouseMs         warehouse time of {@code to}'s command
 * @param wallMillis          wall time (epoch ms) of {@code to}'s command
 */
@JsonPropertyOrder({"robot", "from", "to", "fromLastWarehouseMs", "fromLastWallMillis", "warehouseMs", "wallMillis"})
public record OwnershipChange(String robot, String from, String to, long fromLastWarehouseMs,
                              long fromLastWallMillis, long warehouseMs, long wallMillis) {

    /** Wall time between the two nodes' commands. */
    public long gapWallMillis() {
        return wallMillis - fromLastWallMillis;
    }
}
