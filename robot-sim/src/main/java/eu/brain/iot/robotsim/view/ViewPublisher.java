package eu.brain.iot.robotsim.view;

import eu.brain.iot.robotsim.world.World;
import java.util.concurrent.atomic.AtomicReferenceArray;

/**
 * The bridge between the world's owner thread and the HTTP threads. The owner calls the publish methods after each
 * step or command; any thread reads the latest immutable views without locking, so a poll never waits for a step.
 * A robot is serialized again only when its view changed.
 */
public final class ViewPublisher {
    private final AtomicReferenceArray<PublishedRobot> robots;
    private final AtomicReferenceArray<DoorView> doors;
    private volatile long step;

    public ViewPublisher(World world) {
        robots = new AtomicReferenceArray<>(world.robotCount());
        doors = new AtomicReferenceArray<>(world.doorCount());
        publishAll(world);
    }

    /** Called by the world's owner thread only. */
    public void publishAll(World world) {
        for (int i = 0; i < world.robotCount(); i++) {
            publishRobot(world, i);
        }
        for (int i = 0; i < world.doorCount(); i++) {
            publishDoor(world, i);
        }
        step = world.step();
    }

    /** Called by the world's owner thread only. */
    public void publishRobot(World world, int index) {
        RobotView view = RobotView.of(world, world.robot(index));
        PublishedRobot old = robots.get(index);
        if (old == null || !old.view().equals(view)) {
            robots.set(index, new PublishedRobot(view, Json.bytes(view)));
        }
    }

    /** Called by the world's owner thread only. */
    public void publishDoor(World world, int index) {
        doors.set(index, DoorView.of(world.door(index)));
    }

    public PublishedRobot robot(int index) {
        return robots.get(index);
    }

    public DoorView door(int index) {
        return doors.get(index);
    }

    /** The step of the last full publication. */
    public long step() {
        return step;
    }
}
