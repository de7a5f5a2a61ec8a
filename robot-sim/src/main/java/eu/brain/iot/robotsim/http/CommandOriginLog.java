package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.view.CommandOrigins;
import eu.brain.iot.robotsim.view.OwnershipChange;
import eu.brain.iot.robotsim.view.RobotCommander;
import java.util.ArrayDeque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.LongSupplier;

/**
 * Records which fabric node sent each robot command ({@code X-Brain-Node}, see {@link CommanderHeader}): per robot
 * the last node and when (warehouse time and wall time), and a bounded log of hand-overs (a command from another
 * node than the last one). The scenario's judge reads it from {@code GET /world} to find two nodes driving one robot
 * at once. Only commands the robot took (answered 2xx) are recorded: a refused one drove nothing. Thread-safe: the
 * world thread records and builds {@code /world}; any thread may read a {@link #snapshot()}; every method holds
 * this object's lock, which guards all of its state.
 */
public final class CommandOriginLog {
    /** Hand-overs kept: a whole fleet of 1,000 robots handed over four times. */
    public static final int DEFAULT_CAPACITY = 4096;

    private static final class Last {
        String node;
        long warehouseMs;
        long wallMillis;
        long commands;
        long handovers;
        OwnershipChange closest;
    }

    private final LongSupplier warehouseMillis;
    private final LongSupplier wallMillis;
    private final int capacity;
    private final Map<String, Last> robots = new TreeMap<>();
    private final ArrayDeque<OwnershipChange> changes = new ArrayDeque<>();
    private long dropped;

    /**
     * @param warehouseMillis the warehouse time now (the last published step times the step's length)
     * @param wallMillis      the wall clock (epoch ms)
     * @param capacity        hand-overs kept in the log
     */
    public CommandOriginLog(LongSupplier warehouseMillis, LongSupplier wallMillis, int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity must be positive, found " + capacity);
        }
        this.warehouseMillis = warehouseMillis;
        this.wallMillis = wallMillis;
        this.capacity = capacity;
    }

    /**
     * The robot took a command from {@code node} ({@link CommanderHeader#UNKNOWN} when it named none); called on
     * the world thread, once the command passed.
     */
    synchronized void record(String robot, String node) {
        long warehouse = warehouseMillis.getAsLong();
        long wall = wallMillis.getAsLong();
        Last last = robots.computeIfAbsent(robot, r -> new Last());
        if (last.node != null && !last.node.equals(node)) {
            OwnershipChange change = new OwnershipChange(robot, last.node, node, last.warehouseMs, last.wallMillis,
                    warehouse, wall);
            last.handovers++;
            if (last.closest == null || change.gapWallMillis() < last.closest.gapWallMillis()) {
                last.closest = change;
            }
            if (changes.size() == capacity) {
                changes.removeFirst();
                dropped++;
            }
            changes.addLast(change);
        }
        last.node = node;
        last.warehouseMs = warehouse;
        last.wallMillis = wall;
        last.commands++;
    }

    public synchronized CommandOrigins snapshot() {
        Map<String, RobotCommander> byRobot = new LinkedHashMap<>();
        robots.forEach((id, l) -> byRobot.put(id, new RobotCommander(l.node, l.warehouseMs, l.wallMillis,
                l.commands, l.handovers, l.closest)));
        return new CommandOrigins(byRobot, List.copyOf(changes), capacity, dropped);
    }
}
