package eu.brain.iot.robotsim.world;

import java.util.Arrays;

/**
 * Shortest paths over the four-neighbour grid, as the robots plan them themselves: A* with the Manhattan distance
 * (exact shortest paths, and far fewer cells visited than breadth-first search when a thousand robots plan at
 * once). Walls are never crossed; doors count as passable (a robot waits in front of a closed door); other robots
 * are ignored (the front sensor deals with them); a robot carrying a cart cannot pass under another cart. Ties are
 * broken the same way every time, so paths are deterministic. Reuses its arrays: owned by the world's owner thread.
 */
final class PathPlanner {
    private static final Heading[] ORDER = Heading.values();

    private final WarehouseMap map;
    private final int[] seen;
    private final int[] closed;
    private final int[] cost;
    private final int[] previous;
    private long[] heapKeys;
    private int[] heapCells;
    private int heapSize;
    private int generation;

    PathPlanner(WarehouseMap map) {
        this.map = map;
        int cells = map.width() * map.height();
        seen = new int[cells];
        closed = new int[cells];
        cost = new int[cells];
        previous = new int[cells];
        heapKeys = new long[Math.min(cells, 1 << 16) + 16];
        heapCells = new int[heapKeys.length];
    }

    /**
     * The cells to travel from start to goal (start excluded, goal included), an empty array when start is the goal,
     * or null when no path exists.
     *
     * @param cartAt floor cart per cell (-1 none), consulted only when {@code loaded}
     */
    int[] plan(int start, int goal, int[] cartAt, boolean loaded) {
        if (start == goal) {
            return new int[0];
        }
        if (!map.terrain(goal).passable() || (loaded && cartAt[goal] >= 0)) {
            return null;
        }
        int width = map.width();
        int goalX = goal % width;
        int goalY = goal / width;
        int stamp = ++generation;
        heapSize = 0;
        seen[start] = stamp;
        cost[start] = 0;
        push(start, distance(start % width, start / width, goalX, goalY), 0);
        while (heapSize > 0) {
            int cell = pop();
            if (closed[cell] == stamp) {
                continue;
            }
            closed[cell] = stamp;
            if (cell == goal) {
                return trace(start, goal);
            }
            int cx = cell % width;
            int cy = cell / width;
            int nextCost = cost[cell] + 1;
            for (Heading h : ORDER) {
                int nx = cx + h.dx();
                int ny = cy + h.dy();
                if (!map.inside(nx, ny)) {
                    continue;
                }
                int next = ny * width + nx;
                if (closed[next] == stamp || (seen[next] == stamp && cost[next] <= nextCost)
                        || !map.terrain(next).passable() || (loaded && cartAt[next] >= 0)) {
                    continue;
                }
                seen[next] = stamp;
                cost[next] = nextCost;
                previous[next] = cell;
                int remaining = distance(nx, ny, goalX, goalY);
                push(next, nextCost + remaining, remaining);
            }
        }
        return null;
    }

    private static int distance(int x, int y, int goalX, int goalY) {
        return Math.abs(x - goalX) + Math.abs(y - goalY);
    }

    private int[] trace(int start, int goal) {
        int length = 0;
        for (int c = goal; c != start; c = previous[c]) {
            length++;
        }
        int[] path = new int[length];
        int i = length;
        for (int c = goal; c != start; c = previous[c]) {
            path[--i] = c;
        }
        return path;
    }

    /** Min-heap on (estimated total, then remaining distance): prefers cells closer to the goal among equals. */
    private void push(int cell, int estimate, int remaining) {
        if (heapSize == heapKeys.length) {
            heapKeys = Arrays.copyOf(heapKeys, heapSize * 2);
            heapCells = Arrays.copyOf(heapCells, heapSize * 2);
        }
        long key = ((long) estimate << 32) | remaining;
        int i = heapSize++;
        while (i > 0) {
            int parent = (i - 1) >>> 1;
            if (heapKeys[parent] <= key) {
                break;
            }
            heapKeys[i] = heapKeys[parent];
            heapCells[i] = heapCells[parent];
            i = parent;
        }
        heapKeys[i] = key;
        heapCells[i] = cell;
    }

    private int pop() {
        int top = heapCells[0];
        long key = heapKeys[--heapSize];
        int cell = heapCells[heapSize];
        int i = 0;
        while (true) {
            int child = 2 * i + 1;
            if (child >= heapSize) {
                break;
            }
            if (child + 1 < heapSize && heapKeys[child + 1] < heapKeys[child]) {
                child++;
            }
            if (heapKeys[child] >= key) {
                break;
            }
            heapKeys[i] = heapKeys[child];
            heapCells[i] = heapCells[child];
            i = child;
        }
        heapKeys[i] = key;
        heapCells[i] = cell;
        return top;
    }
}
