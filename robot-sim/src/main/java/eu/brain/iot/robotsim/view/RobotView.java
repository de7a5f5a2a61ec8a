package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import eu.brain.iot.robotsim.world.Robot;
import eu.brain.iot.robotsim.world.World;

/**
 * The answer of {@code GET /{robot}/robot_local_control/state}; immutable, compared to skip re-serializing robots
 * that did not change in a step.
 *
 * @param area      the paper's area code of the robot's cell: 0 corridor, 1 docking, 2 unload, 3 storage, 5 door
 * @param state     "running" (working on a mission, nothing in front) or "stopped"
 * @param detect    0 nothing in front, 1 a robot, 2 a door that is not open
 * @param cart      id of the carried cart, or null
 * @param mission   the running mission, else the next queued, else the last ended; null before the first order
 * @param waitSteps        steps spent stopped behind another robot, all waits together
 * @param longestWaitSteps the longest single wait behind another robot, in steps
 */
@JsonPropertyOrder({"id", "x", "y", "heading", "area", "state", "detect", "cart", "mission", "nearMisses",
        "deadlocks", "waitSteps", "longestWaitSteps"})
public record RobotView(String id, int x, int y, String heading, int area, String state, int detect, String cart,
                        MissionView mission, long nearMisses, long deadlocks, long waitSteps,
                        long longestWaitSteps) {

    public static RobotView of(World world, Robot r) {
        return new RobotView(r.id(), r.x(), r.y(), r.heading().name(),
                world.map().terrain(r.x(), r.y()).area(),
                r.running() ? "running" : "stopped", r.detect(),
                r.carried() >= 0 ? world.cart(r.carried()).id() : null,
                MissionView.of(r.shownMission()), r.nearMisses(), r.deadlocks(),
                r.waitSteps(), r.longestWaitSteps());
    }
}
