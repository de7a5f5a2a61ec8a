package eu.brain.iot.edge.api;

/** Send a robot to a grid cell; the robot plans its own path. */
public class GoToCommand extends EdgeCommand {

    public int x;
    public int y;
}
