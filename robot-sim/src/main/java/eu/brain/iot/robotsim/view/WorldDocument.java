package eu.brain.iot.robotsim.view;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import eu.brain.iot.robotsim.world.Cart;
import eu.brain.iot.robotsim.world.Terrain;
import eu.brain.iot.robotsim.world.World;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** Builds the JSON documents of the world endpoints. Called on the world's owner thread. */
public final class WorldDocument {
    private WorldDocument() {
    }

    /**
     * One robot's counters. A wait is a run of consecutive steps stopped behind another robot ({@code detect} 1).
     *
     * @param waitSteps        steps spent waiting behind another robot, all waits together
     * @param waitingSteps     length of the wait going on now (0: not waiting)
     * @param longestWaitSteps the longest single wait so far (the one going on now included)
     * @param longestWaitMs    the same in warehouse milliseconds
     * @param waitsEnded       waits that have ended
     */
    @JsonPropertyOrder({"nearMisses", "deadlocks", "waitSteps", "waitingSteps", "longestWaitSteps", "longestWaitMs",
            "waitsEnded"})
    public record RobotCounters(long nearMisses, long deadlocks, long waitSteps, long waitingSteps,
                                long longestWaitSteps, long longestWaitMs, long waitsEnded) {
    }

    /** Missions that ended, all robots together. */
    @JsonPropertyOrder({"finished", "failed", "cancelled"})
    public record MissionCounts(long finished, long failed, long cancelled) {
    }

    /** One door's counters: how many times it began to open (closed or closing to opening or open). */
    public record DoorCounters(long openings) {
    }

    /** {@code GET /world} without commands' origins (none recorded). */
    public static Map<String, Object> world(World w, long stepMillis, CommandCounts commands) {
        return world(w, stepMillis, commands, CommandOrigins.NONE);
    }

    /** {@code GET /world}: the map, robots, carts, doors, counters and which node commanded each robot. */
    public static Map<String, Object> world(World w, long stepMillis, CommandCounts commands,
                                            CommandOrigins origins) {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("name", w.map().name());
        doc.put("step", w.step());
        doc.put("width", w.map().width());
        doc.put("height", w.map().height());
        doc.put("map", w.map().terrainRows());
        List<RobotView> robots = new ArrayList<>(w.robotCount());
        for (int i = 0; i < w.robotCount(); i++) {
            robots.add(RobotView.of(w, w.robot(i)));
        }
        doc.put("robots", robots);
        List<CartView> carts = new ArrayList<>(w.cartCount());
        for (int i = 0; i < w.cartCount(); i++) {
            carts.add(CartView.of(w, w.cart(i)));
        }
        doc.put("carts", carts);
        List<DoorView> doors = new ArrayList<>(w.doorCount());
        for (int i = 0; i < w.doorCount(); i++) {
            doors.add(DoorView.of(w.door(i)));
        }
        doc.put("doors", doors);
        doc.put("counters", counters(w, stepMillis, commands));
        doc.put("commandOrigins", origins);
        return doc;
    }

    /**
     * {@code GET /world/counters}: near misses, waits behind another robot, deadlocks, door openings and carts in
     * storage, in total and per robot and door.
     *
     * @param stepMillis warehouse time of one step, to give waits in milliseconds too
     * @param commands   the commands the fleet answered over HTTP (kept outside the world, by the server)
     */
    public static Map<String, Object> counters(World w, long stepMillis, CommandCounts commands) {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("step", w.step());
        doc.put("stepMillis", stepMillis);
        doc.put("nearMisses", w.nearMisses());
        doc.put("deadlocks", w.deadlocks());
        long waitSteps = 0;
        long longest = 0;
        long waitingNow = 0;
        long ended = 0;
        long finished = 0;
        long failed = 0;
        long cancelled = 0;
        Map<String, RobotCounters> perRobot = new LinkedHashMap<>();
        for (int i = 0; i < w.robotCount(); i++) {
            var r = w.robot(i);
            perRobot.put(r.id(), new RobotCounters(r.nearMisses(), r.deadlocks(), r.waitSteps(), r.waitingSteps(),
                    r.longestWaitSteps(), r.longestWaitSteps() * stepMillis, r.waitsEnded()));
            waitSteps += r.waitSteps();
            longest = Math.max(longest, r.longestWaitSteps());
            waitingNow += r.waitingSteps() > 0 ? 1 : 0;
            ended += r.waitsEnded();
            finished += r.missionsFinished();
            failed += r.missionsFailed();
            cancelled += r.missionsCancelled();
        }
        doc.put("waitSteps", waitSteps);
        doc.put("longestWaitSteps", longest);
        doc.put("longestWaitMs", longest * stepMillis);
        doc.put("waitingNow", waitingNow);
        doc.put("waitsEnded", ended);
        doc.put("endedWaits", w.endedWaits());
        long openings = 0;
        Map<String, DoorCounters> perDoor = new LinkedHashMap<>();
        for (int i = 0; i < w.doorCount(); i++) {
            var d = w.door(i);
            perDoor.put(d.id(), new DoorCounters(d.openings()));
            openings += d.openings();
        }
        doc.put("doorOpenings", openings);
        doc.put("carts", w.cartCount());
        doc.put("cartsInStorage", cartsInStorage(w));
        doc.put("commands", commands);
        doc.put("missions", new MissionCounts(finished, failed, cancelled));
        doc.put("perRobot", perRobot);
        doc.put("perDoor", perDoor);
        return doc;
    }

    /** Carts standing (not carried) on a storage cell. */
    static long cartsInStorage(World w) {
        long n = 0;
        for (int i = 0; i < w.cartCount(); i++) {
            Cart c = w.cart(i);
            n += c.carriedBy() < 0 && w.map().terrain(c.x(), c.y()) == Terrain.STORAGE ? 1 : 0;
        }
        return n;
    }
}
