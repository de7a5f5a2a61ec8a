package eu.brain.iot.robotsim.view;

import eu.brain.iot.robotsim.world.World;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** Builds the JSON documents of the world endpoints. Called on the world's owner thread. */
public final class WorldDocument {
    private WorldDocument() {
    }

    /** One robot's counters. */
    @com.fasterxml.jackson.annotation.JsonPropertyOrder({"nearMisses", "deadlocks"})
    public record RobotCounters(long nearMisses, long deadlocks) {
    }

    /** {@code GET /world}: the map, robots, carts, doors and counters. */
    public static Map<String, Object> world(World w) {
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
        doc.put("counters", counters(w));
        return doc;
    }

    /** {@code GET /world/counters}: near misses and deadlocks, in total and per robot. */
    public static Map<String, Object> counters(World w) {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("step", w.step());
        doc.put("nearMisses", w.nearMisses());
        doc.put("deadlocks", w.deadlocks());
        Map<String, RobotCounters> perRobot = new LinkedHashMap<>();
        for (int i = 0; i < w.robotCount(); i++) {
            var r = w.robot(i);
            perRobot.put(r.id(), new RobotCounters(r.nearMisses(), r.deadlocks()));
        }
        doc.put("perRobot", perRobot);
        return doc;
    }
}
