package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;
import java.util.Map;

/**
 * Which fabric node commanded each robot (the {@code commandOrigins} of {@code GET /world}): per robot the last
 * commanding node, and the log of hand-overs, oldest first, bounded to {@code changesKept} entries (older ones are
 * dropped and counted). Immutable.
 *
 * @param robots         per robot that received a command: its last commander
 * @param changes        the hand-overs kept, oldest first
 * @param changesKept    the log's bound
 * @param changesDropped hand-overs dropped from the log because it was full
 */
@JsonPropertyOrder({"robots", "changes", "changesKept", "changesDropped"})
public record CommandOrigins(Map<String, RobotCommander> robots, List<OwnershipChange> changes, int changesKept,
                             long changesDropped) {
    public static final CommandOrigins NONE = new CommandOrigins(Map.of(), List.of(), 0, 0);
}
