package eu.brain.iot.edge.integration;

import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.robotsim.view.RobotView;

/** Commands for the edge, and what the simulator says of a mission: for the unit and the in-framework tests. */
public final class EdgeCommands {

    private EdgeCommands() {
    }

    public static GoToCommand goTo(String robot, int x, int y) {
        GoToCommand g = to(new GoToCommand(), robot);
        g.x = x;
        g.y = y;
        return g;
    }

    /** The command, for that robot or door. */
    public static <C extends EdgeCommand> C to(C command, String device) {
        command.deviceId = device;
        return command;
    }

    /** The robot's current mission is that one, and it is finished. */
    public static boolean finished(RobotView robot, long mission) {
        return robot.mission() != null && robot.mission().id() == mission
                && robot.mission().state().equals("finished");
    }
}
