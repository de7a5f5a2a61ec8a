package eu.brain.iot.edge.impl;

import java.util.ArrayList;
import java.util.List;

/**
 * A robot's answer to {@code GET /{robot}/robot_local_control/state}, checked by {@link AnswerParser}.
 *
 * @param mission the running mission, else the next queued, else the last ended; {@code null} before any
 */
record RobotAnswer(String id, int x, int y, String heading, int area, String state, int detect, String cart,
        Mission mission, int nearMisses, int deadlocks) implements DeviceAnswer {

    /** @param goalX the goal of a {@code goto}, else {@code null} */
    record Mission(long id, String type, String state, String reason, Integer goalX, Integer goalY) {

        boolean ended() {
            return "finished".equals(state) || "failed".equals(state);
        }
    }

    @Override
    public List<Resource> resources() {
        List<Resource> r = new ArrayList<>(18);
        r.add(new Resource("position", "x", x));
        r.add(new Resource("position", "y", y));
        r.add(new Resource("position", "heading", heading));
        r.add(new Resource("position", "area", area));
        r.add(new Resource("state", "state", state));
        r.add(new Resource("state", "detect", detect));
        r.add(new Resource("state", "obstacle", EdgeEvents.kind(detect) == null ? null
                : EdgeEvents.kind(detect).name()));
        r.add(new Resource("cart", "cart", cart));
        r.add(new Resource("cart", "carrying", cart != null));
        Mission m = mission;
        r.add(new Resource("mission", "id", m == null ? null : m.id()));
        r.add(new Resource("mission", "type", m == null ? null : m.type()));
        r.add(new Resource("mission", "state", m == null ? null : m.state()));
        r.add(new Resource("mission", "reason", m == null ? null : m.reason()));
        r.add(new Resource("mission", "goalX", m == null ? null : m.goalX()));
        r.add(new Resource("mission", "goalY", m == null ? null : m.goalY()));
        r.add(new Resource("counters", "nearMisses", nearMisses));
        r.add(new Resource("counters", "deadlocks", deadlocks));
        return r;
    }

    @Override
    public void announce(EdgeEvents events, DeviceAnswer before, java.time.Instant at) {
        events.robot((RobotAnswer) before, this, at); // a provider's answers are all of its kind
    }
}
