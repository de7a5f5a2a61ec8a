package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.List;

/**
 * The fleet's world ({@code GET /world}), checked by {@link AnswerParser}: the map and where every cart stands.
 * Its parts enter the {@link DeviceStore} as providers of their own (a {@link Cart} per cart, the {@link Map} as
 * provider {@value #WAREHOUSE}), so readers of the device model, SSE and the REST API see them like robots and
 * doors. They announce no bus event: a cart's moves are the robots' {@code CartLifted}/{@code CartPlaced}.
 */
record WorldAnswer(Map map, List<Cart> carts) {

    /** The id of the map's provider. */
    static final String WAREHOUSE = "warehouse";

    WorldAnswer {
        carts = List.copyOf(carts);
    }

    /**
     * One cart.
     *
     * @param carriedBy the robot that carries it, or {@code null} when it stands on the floor
     */
    record Cart(String id, int x, int y, String carriedBy) implements DeviceAnswer {
        @Override
        public List<Resource> resources() {
            return List.of(new Resource("position", "x", x), new Resource("position", "y", y),
                    new Resource("cart", "carriedBy", carriedBy));
        }

        @Override
        public void announce(EdgeEvents events, DeviceAnswer before, Instant at) {
            // no event of its own: the robot that lifts or places it announces that
        }
    }

    /**
     * The warehouse's map as the fleet draws it (robot-sim's map format without robots and carts).
     *
     * @param rows the grid's rows, top first, joined by {@code '\n'} (one resource value)
     */
    record Map(String id, String name, int width, int height, String rows) implements DeviceAnswer {
        @Override
        public List<Resource> resources() {
            return List.of(new Resource("map", "name", name), new Resource("map", "width", width),
                    new Resource("map", "height", height), new Resource("map", "rows", rows));
        }

        @Override
        public void announce(EdgeEvents events, DeviceAnswer before, Instant at) {
            // the map does not change while the fleet runs: nothing to announce
        }
    }
}
