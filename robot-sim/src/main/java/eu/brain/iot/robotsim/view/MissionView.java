package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import eu.brain.iot.robotsim.world.Mission;
import eu.brain.iot.robotsim.world.MissionType;

/**
 * A mission as JSON: {@code {"id":3,"type":"goto","state":"running","reason":null,"goal":{"x":5,"y":3}}};
 * goal is null for pick and place, reason is set only for failed missions.
 */
@JsonPropertyOrder({"id", "type", "state", "reason", "goal"})
public record MissionView(long id, String type, String state, String reason, Goal goal) {

    /** A GOTO goal cell. */
    public record Goal(int x, int y) {
    }

    public static MissionView of(Mission m) {
        if (m == null) {
            return null;
        }
        Goal goal = m.type() == MissionType.GOTO ? new Goal(m.goalX(), m.goalY()) : null;
        return new MissionView(m.id(), m.type().jsonName(), m.state().jsonName(), m.reason(), goal);
    }
}
