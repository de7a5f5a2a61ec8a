package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.Map;

/**
 * Commands the fleet received over HTTP (mission add and cancel on a robot, door commands) and how they were
 * answered: accepted (2xx) or refused (any other status, or a dropped connection, counted as status 0).
 *
 * @param refusedByStatus refused commands per HTTP status ("503": the robot was offline, "422", "429", ...)
 */
@JsonPropertyOrder({"received", "accepted", "refused", "refusedByStatus"})
public record CommandCounts(long received, long accepted, long refused, Map<String, Long> refusedByStatus) {
    public static final CommandCounts NONE = new CommandCounts(0, 0, 0, Map.of());
}
