package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.Arrays;
import java.util.function.IntPredicate;

/**
 * One robot's best path over the window through the others' reservations: A* over (cell, step), a step being a
 * move to a neighbour or a wait; each step costs 1 except waiting on the goal (1 more in a passage, 2 more in front
 * of a passage's end while robots come out of it), and the window's end adds the
 * distance still to go, so the first node popped at the window's end is the best. Passages (lanes of one-cell width
 * joining two open cells, doorways) are driven one way at a time ({@link PassageClaims}), so no robot is ever caught
 * in one by a robot coming the other way.
 * <p>
 * <b>A corner costs a step.</b> Robots drive legs in straight lines (a go-to per leg, {@code TrafficControl}), and
 * robot-sim ends a go-to in the step after the robot arrives: the robot stands at every corner for that step. So a
 * move in another direction than the move before it costs one more, and of two paths the one with fewer corners
 * wins where they take as long in fact. The plan's later steps still put the robot a step ahead per corner; they
 * are planned again every step, and the leg a robot drives is given exactly ({@code committed}). A node keeps the
 * move it was first reached by, so a corner's cost is a good guess, not always the best.
 * <p>
 * Arrays are reused (stamped per search): owned by the planner's thread.
 */
final class SpaceTimeSearch {
    private final TrafficMap map;
    private final ReservationTable table;
    private final int window;
    private final int cells;
    private final int maxExpansions;
    private int depthHint;
    /**
     * Per node (step * cells + cell): the search that saw it last in the high 32 bits, {@link #CLOSED} once
     * expanded, its cost so far in the low 31 bits; one read tells whether a node is new, open or done.
     */
    private final long[] mark;
    private final int[] parent;
    private final int[] banned;
    private PassageClaims claims = new PassageClaims();
    /** Cells the robot may not enter at all in the next searches (robots that cannot make way), or null. */
    private IntPredicate immovable;
    /** Each node's direction in the passage it is in (+1 towards end B, -1 towards A, 0 none). */
    private final byte[] heading;
    private final int[] bannedUntil;
    private static final int[] NO_CELLS = new int[0];
    private static final long CLOSED = 1L << 31;
    private static final long COST = CLOSED - 1;
    private long[] heapKeys = new long[1024];
    private int[] heapNodes = new int[1024];
    private int heapSize;
    /** Whether the last search ended with no node left to expand. */
    private boolean exhausted;
    private int generation;
    private long expansions;

    SpaceTimeSearch(TrafficMap map, ReservationTable table, int maxExpansions) {
        this.map = map;
        this.table = table;
        this.window = table.window();
        this.cells = map.cells();
        this.maxExpansions = maxExpansions;
        int nodes = cells * (window + 1);
        mark = new long[nodes];
        parent = new int[nodes];
        banned = new int[cells];
        heading = new byte[nodes];
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
        return find(robot, start, goal, distance, blocked, NO_CELLS, NO_CELLS, 0);
    }

    /**
     * As {@link #find(int, int, int, int[], boolean[])}, with cells kept clear for a while: the robot does not enter
     * {@code forbidden[i]} before step {@code forbiddenUntil[i] + 1} (it gives the robot standing there time to go).
     */
    int[] find(int robot, int start, int goal, int[] distance, boolean[] blocked, int[] forbidden,
               int[] forbiddenUntil, int startHeading) {
        return find(robot, start, goal, distance, blocked, forbidden, forbiddenUntil, startHeading, NO_CELLS);
    }

    /**
     * As above, the robot's first steps given: {@code committed[i]} is its cell at step i + 1 (a leg it was sent on
     * and drives along now).
     */
    int[] find(int robot, int start, int goal, int[] distance, boolean[] blocked, int[] forbidden,
               int[] forbiddenUntil, int startHeading, int[] committed) {
        int stamp = ++generation;
        exhausted = false;
        for (int i = 0; i < forbidden.length; i++) {
            banned[forbidden[i]] = stamp;
            bannedUntil[forbidden[i]] = forbiddenUntil[i];
        }
        heapSize = 0;
        long seenNow = (long) stamp << 32;
        int startNode = start;
        mark[startNode] = seenNow;
        parent[startNode] = -1;
        heading[startNode] = (byte) startHeading;
        push(startNode, h(distance, start), 0);
        int budget = maxExpansions / (1 + 3 * Math.min(1, depthHint));
        while (heapSize > 0 && budget-- > 0) {
            int node = pop();
            long m = mark[node]; // seen in this search: it was pushed in it
            if ((m & CLOSED) != 0) {
                continue;
            }
            mark[node] = m | CLOSED;
            int gNode = (int) (m & COST);
            expansions++;
            int t = node / cells;
            int cell = node - t * cells;
            if (t == window) {
                return trace(node);
            }
            int nt = t + 1;
            int[] next = map.neighbours(cell);
            int came = t == 0 ? -1 : parent[node] - (t - 1) * cells; // its cell a step before, -1 at the start
            int lastMove = came < 0 || came == cell ? 0 : cell - came;
            for (int i = -1; i < next.length; i++) {
                int n = i < 0 ? cell : next[i];
                if (t < committed.length) {
                    if (n != committed[t]) {
                        continue;
                    }
                }
                int child = nt * cells + n;
                long cm = mark[child];
                boolean seenBefore = (int) (cm >>> 32) == stamp;
                if (seenBefore && (cm & CLOSED) != 0) {
                    continue;
                }
                if (n != cell && (banned[n] == stamp && nt <= bannedUntil[n]
                        || n != goal && blocked != null && blocked[n]
                        || immovable != null && immovable.test(n))) {
                    continue;
                }
                if (distance[n] >= Distances.UNREACHABLE || !table.free(robot, n, nt)) {
                    continue;
                }
                int dir = passageHeading(robot, cell, n, heading[node], nt);
                if (dir == 2) {
                    continue;
                }
                // a step in a passage costs one more: robots get out of passages rather than wait in them
                // and two more where a passage lets robots out (they wait elsewhere, not in front of its end)
                int cost = gNode + (n == goal && cell == goal ? 0 : 1) + (map.passage(n) >= 0 ? 1 : 0)
                        + (outlet(robot, n, nt) ? 2 : 0)
                        + (t >= committed.length && n != cell && lastMove != 0 && n - cell != lastMove ? 1 : 0);
                if (seenBefore && (cm & COST) <= cost) {
                    continue;
                }
                mark[child] = seenNow | cost;
                parent[child] = node;
                heading[child] = (byte) dir;
                push(child, cost + h(distance, n), nt);
            }
        }
        exhausted = heapSize == 0;
        return null;
    }

    /**
     * @return whether the last search that found no path tried every step it could take (rather than running out
     *         of its budget): then no path at all reaches the window's end, whatever the goal, as the cells a
     *         robot may enter do not depend on its goal (but for a cart on the goal, see {@code blocked})
     */
    boolean exhausted() {
        return exhausted;
    }

    /** How deep in a chain of pushes the next searches are (a pushed robot needs a way out, not the best path). */
    void depth(int depth) {
        this.depthHint = depth;
    }

    /**
     * Cells the next searches keep out of for the whole window (robots standing there that cannot be pushed), or
     * null for none.
     */
    void immovable(IntPredicate cells) {
        this.immovable = cells;
    }

    /** The passages' claims this round (the planner's, read at every search). */
    void claims(PassageClaims passageClaims) {
        this.claims = passageClaims;
    }

    /**
     * The robot's direction after moving from cell (direction {@code before}) to n at step t, or 2 when the move
     * would meet a robot coming the other way in a passage.
     */
    private int passageHeading(int robot, int cell, int n, int before, int t) {
        int run = map.passage(n);
        if (run < 0) {
            return 0;
        }
        int dir = n == cell ? before : moveDirection(map, cell, n, run);
        if (dir == 0) {
            dir = before != 0 ? before : 1;
        }
        return claims.against(robot, run, dir, t) ? 2 : dir;
    }

    /** Whether robots come out of a passage into this cell at step t (nobody may wait there then). */
    private boolean outlet(int robot, int cell, int t) {
        if (!map.passageExit(cell)) {
            return false;
        }
        for (int n : map.neighbours(cell)) {
            int run = map.passage(n);
            if (run >= 0) {
                int side = map.passageExit(run, 1) == cell ? 1 : map.passageExit(run, 0) == cell ? 0 : -1;
                if (side >= 0 && claims.along(robot, run, side == 1 ? 1 : -1, t)) {
                    return true;
                }
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
