package eu.brain.iot.behaviours.robot.impl;

import eu.brain.iot.behaviours.events.RobotBehaviorFromUnloadObstacle;
import eu.brain.iot.behaviours.events.RobotBehaviorStorageToDocking;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadLocation;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadToStorage;
import eu.brain.iot.behaviours.events.RobotBehaviorUnloadToUnload;
import eu.brain.iot.behaviours.warehouse.RobotNames;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The robot model's ports the environment drives (Robot.bip's exported status ports), and the generated event of
 * each for a robot's instance: robot-sim's {@code robotK} is component {@code Robot<(K-1)%3+1>} of group
 * {@code g<ceil(K/3)>} ({@link RobotNames}).
 */
enum ModelPort {
    UNLOAD_LOCATION, UNLOAD_TO_UNLOAD, FROM_UNLOAD_OBSTACLE, UNLOAD_TO_STORAGE, STORAGE_TO_DOCKING;

    /** @return the port's event for the robot's instance, with its data */
    BrainIoTEvent event(String robot, double position, int detect) {
        int k = RobotNames.number(robot);
        String group = RobotNames.group(k);
        String component = RobotNames.component(k);
        return switch (this) {
            case UNLOAD_LOCATION -> {
                RobotBehaviorUnloadLocation e = new RobotBehaviorUnloadLocation();
                e.group = group;
                e.component = component;
                e.position = position;
                e.detect = detect;
                yield e;
            }
            case UNLOAD_TO_UNLOAD -> {
                RobotBehaviorUnloadToUnload e = new RobotBehaviorUnloadToUnload();
                e.group = group;
                e.component = component;
                e.position = position;
                e.detect = detect;
                yield e;
            }
            case FROM_UNLOAD_OBSTACLE -> {
                RobotBehaviorFromUnloadObstacle e = new RobotBehaviorFromUnloadObstacle();
                e.group = group;
                e.component = component;
                e.position = position;
                e.detect = detect;
                yield e;
            }
            case UNLOAD_TO_STORAGE -> {
                RobotBehaviorUnloadToStorage e = new RobotBehaviorUnloadToStorage();
                e.group = group;
                e.component = component;
                e.position = position;
                e.detect = detect;
                yield e;
            }
            case STORAGE_TO_DOCKING -> {
                RobotBehaviorStorageToDocking e = new RobotBehaviorStorageToDocking();
                e.group = group;
                e.component = component;
                e.position = position;
                e.detect = detect;
                yield e;
            }
        };
    }
}
