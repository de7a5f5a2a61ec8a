package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Exact distances to a cell through the terrain (robots and carts ignored): the planner's heuristic and its cost
 * beyond the window. Two kinds:
 * <ul>
 * <li>{@link #to}: to a robot's goal, from every cell, one breadth-first search per goal, kept for the goals used
 * most recently (a robot keeps its goal for many rounds). A table dropped from the cache is reused for the next
 * goal, so a long run allocates no more tables than it keeps.</li>
 * <li>{@link #around}: to a robot's own cell, only within a radius (the window): a robot making way never gets
 * further than the window from where it stands, so a search of a few hundred cells serves it, and these tables are
 * not cached (robots make way from ever new cells and would push the goals out of the cache).</li>
 * </ul>
 * Owned by the planner's thread (not thread-safe).
 */
final class Distances {
    /** Distance of a cell from which the goal cannot be reached. */
    static final int UNREACHABLE = Integer.MAX_VALUE / 4;

    private final TrafficMap map;
    private final Map<Integer, int[]> cache;
    /** Tables dropped from the cache, to be filled again. */
    private final Deque<int[]> spare = new ArrayDeque<>();
    private final int[] queue;
    /** The table {@link #around} fills: UNREACHABLE except at the cells listed in {@link #touched}. */
    private final int[] near;
    private final int[] touched;
    private int touchedCount;

    /**
     * @param keep how many goals' tables to keep (at least the robots' count: every robot's goal is asked for in
     *             every round, so fewer would search again every round)
     */
    Distances(TrafficMap map, int keep) {
        this.map = map;
        this.queue = new int[map.cells()];
        this.near = new int[map.cells()];
        this.touched = new int[map.cells()];
        Arrays.fill(near, UNREACHABLE);
        this.cache = new LinkedHashMap<>(16, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Integer, int[]> eldest) {
                if (size() > keep) {
                    spare.push(eldest.getValue());
                    return true;
                }
                return false;
            }
        };
    }

    /** The distance from every cell to the goal ({@link #UNREACHABLE} where there is no path). Do not modify. */
    int[] to(int goal) {
        int[] d = cache.get(goal);
        if (d == null) {
            d = spare.isEmpty() ? new int[map.cells()] : spare.pop();
            Arrays.fill(d, UNREACHABLE);
            search(goal, d, Integer.MAX_VALUE);
            cache.put(goal, d);
        }
        return d;
    }

    /**
     * The distance to {@code cell} from every cell at most {@code radius} steps from it, {@link #UNREACHABLE} from
     * the others. The table is valid until the next call (it is reused). Do not modify.
     */
    int[] around(int cell, int radius) {
        for (int i = 0; i < touchedCount; i++) {
            near[touched[i]] = UNREACHABLE;
        }
        touchedCount = search(cell, near, radius);
        System.arraycopy(queue, 0, touched, 0, touchedCount);
        return near;
    }

    /**
     * Breadth-first search from the goal over the passable cells up to the radius, into d (UNREACHABLE everywhere
     * before). The cells reached are left in {@link #queue}.
     *
     * @return how many cells were reached
     */
    private int search(int goal, int[] d, int radius) {
        if (!map.passable(goal)) {
            return 0;
        }
        int head = 0;
        int tail = 0;
        d[goal] = 0;
        queue[tail++] = goal;
        while (head < tail) {
            int c = queue[head++];
            if (d[c] >= radius) {
                continue;
            }
            for (int n : map.neighbours(c)) {
                if (d[n] == UNREACHABLE) {
                    d[n] = d[c] + 1;
                    queue[tail++] = n;
                }
            }
        }
        return tail;
    }
}
