package eu.brain.iot.behaviours.robot.impl;

import java.util.function.Supplier;

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
 * {@code g<ceil(K/3)>} ({@link RobotNames}). The generated events share no supertype with their data, so it is set by
 * the fields' names, the same in each ({@code group}, {@code component}, {@code position}, {@code detect}: the port
 * type {@code Port_Robot_Status}).
 */
enum ModelPort {
    UNLOAD_LOCATION(RobotBehaviorUnloadLocation::new),
    UNLOAD_TO_UNLOAD(RobotBehaviorUnloadToUnload::new),
    FROM_UNLOAD_OBSTACLE(RobotBehaviorFromUnloadObstacle::new),
    UNLOAD_TO_STORAGE(RobotBehaviorUnloadToStorage::new),
    STORAGE_TO_DOCKING(RobotBehaviorStorageToDocking::new);

    private final Supplier<BrainIoTEvent> event;

    ModelPort(Supplier<BrainIoTEvent> event) {
        this.event = event;
    }

    /** @return the port's event for the robot's instance, with its data */
    BrainIoTEvent event(String robot, double position, int detect) {
        int k = RobotNames.number(robot);
        BrainIoTEvent e = event.get();
        try {
            e.getClass().getField("group").set(e, RobotNames.group(k));
            e.getClass().getField("component").set(e, RobotNames.component(k));
            e.getClass().getField("position").setDouble(e, position);
            e.getClass().getField("detect").setInt(e, detect);
        } catch (ReflectiveOperationException notThePortType) { // the generator changed Port_Robot_Status
            throw new IllegalStateException(e.getClass().getName() + " lacks a field of Port_Robot_Status",
                    notThePortType);
        }
        return e;
    }
}
