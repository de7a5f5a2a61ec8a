package eu.brain.iot.robotsim.world;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The whole mutable state of the warehouse: robots, carts, doors, who stands where, the counters.
 * <p>
 * Not thread-safe by design: exactly one owner thread mutates and reads it (in a running simulator the world
 * thread of {@code eu.brain.iot.robotsim.WorldThread}). Everything other threads need is published as immutable
 * views.
 */
public final class World {
    final WarehouseMap map;
    final SimRules rules;
    final Robot[] robots;
    final Cart[] carts;
    final Door[] doors;
    /** Per cell: index of the robot standing there, or -1. */
    final int[] robotAt;
    /** Per cell: index of the cart standing on the floor there (not carried), or -1. */
    final int[] cartAt;
    /** Per cell: index of the door there, or -1. */
    final int[] doorAt;
    final PathPlanner planner;
    private final Map<String, Integer> robotIndex = new HashMap<>();
    private final Map<String, Integer> doorIndex = new HashMap<>();
    long step;
    long nextMissionId = 1;
    long nearMisses;
    long deadlocks;
    /** Waits behind another robot that have ended: length in steps to how many. */
    final java.util.TreeMap<Long, Long> endedWaits = new java.util.TreeMap<>();

    public World(WarehouseMap map, SimRules rules) {
        this.map = map;
        this.rules = rules;
        int cells = map.width() * map.height();
        robotAt = filled(cells);
        cartAt = filled(cells);
        doorAt = filled(cells);
        planner = new PathPlanner(map);
        List<Placement> rs = map.robots();
        robots = new Robot[rs.size()];
        for (int i = 0; i < robots.length; i++) {
            Placement p = rs.get(i);
            robots[i] = new Robot(i, p.id(), p.x(), p.y());
            robotAt[cell(p.x(), p.y())] = i;
            robotIndex.put(p.id(), i);
        }
        List<Placement> cs = map.carts();
        carts = new Cart[cs.size()];
        for (int i = 0; i < carts.length; i++) {
            Placement p = cs.get(i);
            carts[i] = new Cart(i, p.id(), p.x(), p.y());
            cartAt[cell(p.x(), p.y())] = i;
        }
        List<Placement> ds = map.doors();
        int openSteps = rules.doorOpenSteps() >= 0 ? rules.doorOpenSteps() : map.doorOpenSteps();
        doors = new Door[ds.size()];
        for (int i = 0; i < doors.length; i++) {
            Placement p = ds.get(i);
            doors[i] = new Door(i, p.id(), p.x(), p.y(), openSteps);
            doorAt[cell(p.x(), p.y())] = i;
            doorIndex.put(p.id(), i);
        }
    }

    private static int[] filled(int n) {
        int[] a = new int[n];
        java.util.Arrays.fill(a, -1);
        return a;
    }

    int cell(int x, int y) {
        return y * map.width() + x;
    }

    public WarehouseMap map() {
        return map;
    }

    public SimRules rules() {
        return rules;
    }

    /** Steps done since the start. */
    public long step() {
        return step;
    }

    public int robotCount() {
        return robots.length;
    }

    public Robot robot(int index) {
        return robots[index];
    }

    /** Index of the robot with this id, or -1. */
    public int robotIndex(String id) {
        return robotIndex.getOrDefault(id, -1);
    }

    public int cartCount() {
        return carts.length;
    }

    public Cart cart(int index) {
        return carts[index];
    }

    public int doorCount() {
        return doors.length;
    }

    public Door door(int index) {
        return doors[index];
    }

    /** Index of the door with this id, or -1. */
    public int doorIndex(String id) {
        return doorIndex.getOrDefault(id, -1);
    }

    /** Robot standing at (x, y), or -1. */
    public int robotAt(int x, int y) {
        return robotAt[cell(x, y)];
    }

    /** Cart on the floor at (x, y) (not carried), or -1. */
    public int cartAt(int x, int y) {
        return cartAt[cell(x, y)];
    }

    /** Stops caused by another robot, all robots together. */
    public long nearMisses() {
        return nearMisses;
    }

    /** Waits behind another robot that have ended, by length in steps (ascending) to how many; a copy. */
    public java.util.SortedMap<Long, Long> endedWaits() {
        return new java.util.TreeMap<>(endedWaits);
    }

    /** Deadlocks (cycles of robots waiting on each other for deadlockSteps steps), all robots together. */
    public long deadlocks() {
        return deadlocks;
    }
}
