package eu.brain.iot.robotsim.world;

/**
 * Breadth-first shortest paths over the four-neighbour grid, as the robots plan them themselves. Walls are never
 * crossed; doors count as passable (a robot waits in front of a closed door); other robots are ignored (the front
 * sensor deals with them); a robot carrying a cart cannot pass under another cart. Neighbours are tried in the
 * order N, E, S, W so paths are deterministic. Reuses its arrays: owned by the world's owner thread.
 */
final class PathPlanner {
    private static final Heading[] ORDER = Heading.values();

    private final WarehouseMap map;
    private final int[] seen;
    private final int[] previous;
    private final int[] queue;
    private int generation;

    PathPlanner(WarehouseMap map) {
        this.map = map;
        int cells = map.width() * map.height();
        seen = new int[cells];
        previous = new int[cells];
        queue = new int[cells];
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
        int stamp = ++generation;
        int head = 0;
        int tail = 0;
        queue[tail++] = start;
        seen[start] = stamp;
        while (head < tail) {
            int cell = queue[head++];
            int cx = cell % width;
            int cy = cell / width;
            for (Heading h : ORDER) {
                int nx = cx + h.dx();
                int ny = cy + h.dy();
                if (!map.inside(nx, ny)) {
                    continue;
                }
                int next = ny * width + nx;
                if (seen[next] == stamp || !map.terrain(next).passable() || (loaded && cartAt[next] >= 0)) {
                    continue;
                }
                seen[next] = stamp;
                previous[next] = cell;
                if (next == goal) {
                    return trace(start, goal);
                }
                queue[tail++] = next;
            }
        }
        return null;
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
}
