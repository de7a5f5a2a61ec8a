package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import eu.brain.iot.robotsim.world.Door;

/** A door as JSON: state closed, opening, open or closing; {@code data} 1.0 when open, else 0.0 (as commanded). */
@JsonPropertyOrder({"id", "x", "y", "state", "data", "stepsLeft"})
public record DoorView(String id, int x, int y, String state, double data, int stepsLeft) {

    public static DoorView of(Door d) {
        return new DoorView(d.id(), d.x(), d.y(), d.state().jsonName(), d.passable() ? 1.0 : 0.0, d.stepsLeft());
    }
}
