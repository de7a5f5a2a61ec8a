package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Exact distances to a goal through the terrain (robots and carts ignored), one breadth-first search per goal,
 * kept for the goals used most recently: the planner's heuristic and its cost beyond the window. Owned by the
 * planner's thread (not thread-safe).
 */
final class Distances {
    /** Distance of a cell from which the goal cannot be reached. */
    static final int UNREACHABLE = Integer.MAX_VALUE / 4;

    private final TrafficMap map;
    private final Map<Integer, int[]> cache;
    private final int[] queue;

    Distances(TrafficMap map, int keep) {
        this.map = map;
        this.queue = new int[map.cells()];
        this.cache = new LinkedHashMap<>(16, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Integer, int[]> eldest) {
                return size() > keep;
            }
        };
    }

    /** The distance from every cell to the goal ({@link #UNREACHABLE} where there is no path). */
    int[] to(int goal) {
        int[] d = cache.get(goal);
        if (d == null) {
            d = search(goal);
            cache.put(goal, d);
        }
        return d;
    }

    private int[] search(int goal) {
        int[] d = new int[map.cells()];
        Arrays.fill(d, UNREACHABLE);
        if (!map.passable(goal)) {
            return d;
        }
        int head = 0;
        int tail = 0;
        d[goal] = 0;
        queue[tail++] = goal;
        while (head < tail) {
            int c = queue[head++];
            for (int n : map.neighbours(c)) {
                if (d[n] == UNREACHABLE) {
                    d[n] = d[c] + 1;
                    queue[tail++] = n;
                }
            }
        }
        return d;
    }
}
