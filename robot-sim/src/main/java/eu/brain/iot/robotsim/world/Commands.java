package eu.brain.iot.robotsim.world;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

/**
 * Orders given to the world from outside (REST or the Java API). A rejected order throws before anything changes.
 * Owned by the world's owner thread, like the {@link World} itself.
 */
public final class Commands {
    /** The default bound of one robot's queue of missions (not counting the running one). */
    public static final int DEFAULT_MAX_QUEUED = 64;

    private final World world;
    private final int maxQueued;

    /** Commands with no bound on a robot's queue (for benchmarks and tests of the rules). */
    public Commands(World world) {
        this(world, Integer.MAX_VALUE);
    }

    /** @param maxQueued missions a robot may have queued (not counting the running one); more are refused */
    public Commands(World world, int maxQueued) {
        if (maxQueued < 1) {
            throw new IllegalArgumentException("maxQueued must be >= 1, was " + maxQueued);
        }
        this.world = world;
        this.maxQueued = maxQueued;
    }

    /** Queues a GOTO; the goal must be inside the map and not a wall. */
    public Mission goTo(int robot, int x, int y) throws CommandRejectedException {
        WarehouseMap map = world.map;
        if (!map.inside(x, y)) {
            String field = x < 0 || x >= map.width() ? "x" : "y";
            throw new CommandRejectedException(CommandRejectedException.Kind.UNPROCESSABLE, field,
                    "goal (" + x + "," + y + ") is outside the " + map.width() + "x" + map.height()
                            + " map (x 0.." + (map.width() - 1) + ", y 0.." + (map.height() - 1) + ")");
        }
        if (!map.terrain(x, y).passable()) {
            throw new CommandRejectedException(CommandRejectedException.Kind.UNPROCESSABLE, "x",
                    "goal (" + x + "," + y + ") is a wall");
        }
        return enqueue(robot, MissionType.GOTO, x, y);
    }

    /** Queues a corkscrew pick of the cart under the robot (checked when the mission starts). */
    public Mission pick(int robot) throws CommandRejectedException {
        return enqueue(robot, MissionType.PICK, -1, -1);
    }

    /** Queues putting the carried cart down where the robot stands (checked when the mission starts). */
    public Mission place(int robot) throws CommandRejectedException {
        return enqueue(robot, MissionType.PLACE, -1, -1);
    }

    private Mission enqueue(int robot, MissionType type, int x, int y) throws CommandRejectedException {
        Robot r = world.robots[robot];
        if (r.queue.size() >= maxQueued) {
            throw new CommandRejectedException(CommandRejectedException.Kind.LIMIT, null,
                    r.id() + "'s mission queue is full: " + r.queue.size() + " missions wait (the bound is "
                            + maxQueued + ", robot-sim's --max-queue): wait until queued missions start, or cancel "
                            + "some (POST .../" + type.component() + "/cancel)");
        }
        Mission m = new Mission(world.nextMissionId++, type, x, y);
        world.robots[robot].queue.addLast(m);
        return m;
    }

    /**
     * Cancels a mission of one component: the given id, or without id the running one of that component, else its
     * first queued one. A cancelled mission ends FAILED with reason "cancelled"; a pick or place in progress is
     * abandoned (the cart stays where it was). Returns what was cancelled (empty when nothing was to cancel).
     */
    public List<Mission> cancel(int robot, MissionType type, Long missionId) throws CommandRejectedException {
        Robot r = world.robots[robot];
        List<Mission> cancelled = new ArrayList<>();
        Mission current = r.current;
        if (current != null && current.type() == type && (missionId == null || current.id() == missionId)) {
            MissionRules.failCurrent(r, "cancelled");
            cancelled.add(current);
            return cancelled;
        }
        for (Iterator<Mission> it = r.queue.iterator(); it.hasNext(); ) {
            Mission m = it.next();
            if (m.type() == type && (missionId == null || m.id() == missionId)) {
                it.remove();
                m.fail("cancelled");
                r.remember(m);
                cancelled.add(m);
                return cancelled;
            }
        }
        if (missionId != null) {
            throw new CommandRejectedException(CommandRejectedException.Kind.NOT_FOUND, "id",
                    "mission " + missionId + " is not queued or running on " + r.id() + "'s " + type.component());
        }
        return cancelled;
    }

    /** Opens ({@code true}) or closes a door. */
    public void door(int door, boolean open) {
        Door d = world.doors[door];
        if (open) {
            d.commandOpen();
        } else {
            d.commandClose(world.robotAt[world.cell(d.x(), d.y())] >= 0);
        }
    }
}
