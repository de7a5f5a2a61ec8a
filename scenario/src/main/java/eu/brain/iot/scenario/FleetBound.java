package eu.brain.iot.scenario;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

import eu.brain.iot.robotsim.world.SimRules;

/**
 * The most carts per warehouse hour the fleet itself could deliver on a map, doors aside: every robot always on an
 * errand, never waiting: robots x 3,600 s over the mean shortest errand, docking -> cart -> storage -> docking
 * (through the doors, as shortest paths run) plus the lift and the put-down. The mean is over the robots' docks, the
 * carts and the storage cells, each leg separately: (dock to cart) + (cart to storage cell) + (storage cell to dock),
 * in steps of the run's step length. Read from the world document at the start (the map's rows, where robots and
 * carts stand). Stateless.
 */
final class FleetBound {
    private static final int[][] STEPS = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};

    private FleetBound() {
    }

    /** @return carts per warehouse hour, or 0 when the map has no robot, cart or storage cell reachable */
    static double cartsPerHour(JsonNode doc, long stepMillis) {
        List<String> rows = new ArrayList<>();
        doc.path("map").forEach(r -> rows.add(r.asText()));
        if (rows.isEmpty()) {
            return 0;
        }
        int width = rows.get(0).length();
        List<Integer> docks = cells(doc.path("robots"), width);
        List<Integer> carts = cells(doc.path("carts"), width);
        List<Integer> storage = new ArrayList<>();
        for (int y = 0; y < rows.size(); y++) {
            for (int x = 0; x < width; x++) {
                if (rows.get(y).charAt(x) == 's') {
                    storage.add(y * width + x);
                }
            }
        }
        if (docks.isEmpty() || carts.isEmpty() || storage.isEmpty()) {
            return 0;
        }
        double toCart = 0;
        double toStorage = 0;
        for (int cart : carts) {
            int[] d = distances(rows, cart);
            toCart += mean(d, docks);
            toStorage += mean(d, storage);
        }
        double home = 0;
        for (int dock : docks) {
            home += mean(distances(rows, dock), storage);
        }
        double steps = toCart / carts.size() + toStorage / carts.size() + home / docks.size()
                + SimRules.DEFAULT.pickSteps() + SimRules.DEFAULT.placeSteps();
        return docks.size() * 3_600_000.0 / (steps * stepMillis);
    }

    private static List<Integer> cells(JsonNode items, int width) {
        List<Integer> cells = new ArrayList<>();
        items.forEach(i -> cells.add(i.path("y").asInt() * width + i.path("x").asInt()));
        return cells;
    }

    private static double mean(int[] distance, List<Integer> cells) {
        double sum = 0;
        int n = 0;
        for (int c : cells) {
            if (distance[c] >= 0) {
                sum += distance[c];
                n++;
            }
        }
        return n == 0 ? 0 : sum / n;
    }

    /** Steps from a cell to every cell through anything but walls (-1: unreachable). */
    private static int[] distances(List<String> rows, int from) {
        int width = rows.get(0).length();
        int[] d = new int[width * rows.size()];
        Arrays.fill(d, -1);
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        d[from] = 0;
        queue.add(from);
        while (!queue.isEmpty()) {
            int c = queue.poll();
            for (int[] s : STEPS) {
                int x = c % width + s[0];
                int y = c / width + s[1];
                if (x >= 0 && y >= 0 && x < width && y < rows.size() && rows.get(y).charAt(x) != '#'
                        && d[y * width + x] < 0) {
                    d[y * width + x] = d[c] + 1;
                    queue.add(y * width + x);
                }
            }
        }
        return d;
    }
}
