package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import eu.brain.iot.robotsim.world.Cart;
import eu.brain.iot.robotsim.world.World;

/** A cart as JSON; {@code carriedBy} is the robot id lifting it, or null when it stands on the floor. */
@JsonPropertyOrder({"id", "x", "y", "carriedBy"})
public record CartView(String id, int x, int y, String carriedBy) {

    public static CartView of(World world, Cart c) {
        return new CartView(c.id(), c.x(), c.y(), c.carriedBy() >= 0 ? world.robot(c.carriedBy()).id() : null);
    }
}
