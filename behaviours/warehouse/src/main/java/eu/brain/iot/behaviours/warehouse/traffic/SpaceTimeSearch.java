package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.Arrays;

/**
 * One robot's best path over the window through the others' reservations: A* over (cell, step), a step being a
 * move to a neighbour or a wait; each step costs 1 except waiting on the goal, and the window's end adds the
 * distance still to go, so the first node popped at the window's end is the best. Passages (lanes of one-cell width
 * joining two open cells, doorways) are one-way while anyone is in them or planned into them
 * ({@link #directions}), so no robot is ever caught in one by a robot coming the other way. Arrays are
 * reused (stamped per search): owned by the planner's thread.
 */
final class SpaceTimeSearch {
    private final TrafficMap map;
    private final ReservationTable table;
    private final int window;
    private final int cells;
    private final int maxExpansions;
    private final int[] g;
    private final int[] parent;
    private final int[] seen;
    private final int[] closed;
    private final int[] banned;
    private int[] direction;
    private final int[] bannedUntil;
    private static final int[] NO_CELLS = new int[0];
    private long[] heapKeys = new long[1024];
    private int[] heapNodes = new int[1024];
    private int heapSize;
    private int generation;
    private long expansions;

    SpaceTimeSearch(TrafficMap map, ReservationTable table, int maxExpansions) {
        this.map = map;
        this.table = table;
        this.window = table.window();
        this.cells = map.cells();
        this.maxExpansions = maxExpansions;
        int nodes = cells * (window + 1);
        g = new int[nodes];
        parent = new int[nodes];
        seen = new int[nodes];
        closed = new int[nodes];
        banned = new int[cells];
        direction = new int[map.passages()];
        bannedUntil = new int[cells];
    }

    /** Nodes expanded by every search so far (for the benchmark). */
    long expansions() {
        return expansions;
    }

    /**
     * @param blocked cells the robot may not enter (the carts, for a robot carrying one), or null
     * @return the robot's cell at each step 0..window (step 0 is {@code start}), or null when no path keeps clear
     *         of the reservations within the search's budget
     */
    int[] find(int robot, int start, int goal, int[] distance, boolean[] blocked) {
        return find(robot, start, goal, distance, blocked, NO_CELLS, NO_CELLS);
    }

    /**
     * As {@link #find(int, int, int, int[], boolean[])}, with cells kept clear for a while: the robot does not enter
     * {@code forbidden[i]} before step {@code forbiddenUntil[i] + 1} (it gives the robot standing there time to go).
     */
    int[] find(int robot, int start, int goal, int[] distance, boolean[] blocked, int[] forbidden,
               int[] forbiddenUntil) {
        int stamp = ++generation;
        for (int i = 0; i < forbidden.length; i++) {
            banned[forbidden[i]] = stamp;
            bannedUntil[forbidden[i]] = forbiddenUntil[i];
        }
        heapSize = 0;
        int startNode = start;
        seen[startNode] = stamp;
        g[startNode] = 0;
        parent[startNode] = -1;
        push(startNode, h(distance, start), 0);
        int budget = maxExpansions;
        while (heapSize > 0 && budget-- > 0) {
            int node = pop();
            if (closed[node] == stamp) {
                continue;
            }
            closed[node] = stamp;
            expansions++;
            int t = node / cells;
            int cell = node - t * cells;
            if (t == window) {
                if (cell == goal || !outletAhead(cell)) {
                    return trace(node);
                }
                continue;
            }
            int nt = t + 1;
            int[] next = map.neighbours(cell);
            boolean mayWait = cell == goal || !outletAhead(cell); // nobody waits where a passage lets robots out
            for (int i = -1; i < next.length; i++) {
                int n = i < 0 ? cell : next[i];
                if (i < 0 && !mayWait) {
                    continue;
                }
                if (n != cell && (banned[n] == stamp && nt <= bannedUntil[n]
                        || n != goal && blocked != null && blocked[n])) {
                    continue;
                }
                if (distance[n] >= Distances.UNREACHABLE || !oneWay(cell, n) || !table.free(robot, n, nt)) {
                    continue;
                }
                int child = nt * cells + n;
                int cost = g[node] + (n == goal && cell == goal ? 0 : 1);
                if (closed[child] == stamp || (seen[child] == stamp && g[child] <= cost)) {
                    continue;
                }
                seen[child] = stamp;
                g[child] = cost;
                parent[child] = node;
                push(child, cost + h(distance, n), nt);
            }
        }
        return null;
    }

    /**
     * Each passage's direction this round: +1 robots drive from end A to end B, -1 from B to A, 0 free (the array is
     * the planner's, read at every search).
     */
    void directions(int[] passageDirections) {
        this.direction = passageDirections;
    }

    /** Whether a move from cell to n keeps to the direction of the passage n is in (leaving a passage always may). */
    private boolean oneWay(int cell, int n) {
        int run = n == cell ? -1 : map.passage(n);
        if (run < 0 || direction[run] == 0) {
            return true;
        }
        return moveDirection(map, cell, n, run) == direction[run];
    }

    /** Whether the cell is where a one-way passage lets robots out (nobody may wait there at the window's end). */
    private boolean outletAhead(int cell) {
        for (int n : map.neighbours(cell)) {
            int run = map.passage(n);
            if (run >= 0 && direction[run] != 0 && map.passageExit(run, direction[run] > 0 ? 1 : 0) == cell) {
                return true;
            }
        }
        return false;
    }

    /** The direction (+1 towards end B, -1 towards A) of a move into or along a passage. */
    static int moveDirection(TrafficMap map, int cell, int n, int run) {
        if (map.passage(cell) == run) {
            return Integer.signum(map.passagePosition(n) - map.passagePosition(cell));
        }
        return cell == map.passageExit(run, 0) ? 1 : -1;
    }

    private static int h(int[] distance, int cell) {
        return distance[cell];
    }

    private int[] trace(int node) {
        int[] path = new int[window + 1];
        for (int n = node; n >= 0; n = parent[n]) {
            int t = n / cells;
            path[t] = n - t * cells;
        }
        return path;
    }

    /** Min-heap on (f, then later steps first): deeper nodes among equals, so the search runs down to the end. */
    private void push(int node, int f, int t) {
        if (heapSize == heapKeys.length) {
            heapKeys = Arrays.copyOf(heapKeys, heapSize * 2);
            heapNodes = Arrays.copyOf(heapNodes, heapSize * 2);
        }
        long key = ((long) f << 16) | (window - t);
        int i = heapSize++;
        while (i > 0) {
            int up = (i - 1) >>> 1;
            if (heapKeys[up] <= key) {
                break;
            }
            heapKeys[i] = heapKeys[up];
            heapNodes[i] = heapNodes[up];
            i = up;
        }
        heapKeys[i] = key;
        heapNodes[i] = node;
    }

    private int pop() {
        int top = heapNodes[0];
        long key = heapKeys[--heapSize];
        int node = heapNodes[heapSize];
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
            heapNodes[i] = heapNodes[child];
            i = child;
        }
        heapKeys[i] = key;
        heapNodes[i] = node;
        return top;
    }
}
