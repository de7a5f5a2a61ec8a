package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * The warehouse's cells as the planner reads them: a cell is an int ({@code y * width + x}), with its passable
 * neighbours in the order N, E, S, W, whether it is a doorway, and whether it is a <em>lane</em> cell: one with at
 * most two passable neighbours, where two robots cannot pass each other (a doorway, a one-cell corridor, a dead
 * end). Immutable, so any thread may read it.
 */
public final class TrafficMap {
    private static final int[][] STEPS = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};

    private final int width;
    private final int height;
    private final boolean[] passable;
    private final boolean[] door;
    private final boolean[] lane;
    /** The passage each cell belongs to, -1 for none. */
    private final int[] runOf;
    /** A passage cell's position from its end A. */
    private final int[] runPos;
    /** Each passage's exits: the open cell beyond end A, the one beyond end B. */
    private int[][] runExits;
    /** Whether a cell is the exit of a passage (the open cell beyond one of its ends). */
    private final boolean[] exit;
    private final int[][] neighbours;
    private final Grid grid;

    private TrafficMap(Grid grid) {
        this.grid = grid;
        this.width = grid.width();
        this.height = grid.height();
        int cells = width * height;
        passable = new boolean[cells];
        door = new boolean[cells];
        lane = new boolean[cells];
        neighbours = new int[cells][];
        for (int c = 0; c < cells; c++) {
            Cell cell = cell(c);
            passable[c] = grid.passable(cell);
            door[c] = grid.area(cell) == Grid.DOORWAY;
        }
        int[] scratch = new int[4];
        for (int c = 0; c < cells; c++) {
            int n = 0;
            if (passable[c]) {
                int x = c % width;
                int y = c / width;
                for (int[] s : STEPS) {
                    int nx = x + s[0];
                    int ny = y + s[1];
                    if (nx >= 0 && ny >= 0 && nx < width && ny < height && passable[ny * width + nx]) {
                        scratch[n++] = ny * width + nx;
                    }
                }
            }
            neighbours[c] = Arrays.copyOf(scratch, n);
            lane[c] = passable[c] && n <= 2;
        }
        runOf = new int[cells];
        runPos = new int[cells];
        Arrays.fill(runOf, -1);
        markThroughLanes();
        exit = new boolean[cells];
        for (int[] ends : runExits) {
            exit[ends[0]] = true;
            exit[ends[1]] = true;
        }
    }

    /**
     * Finds the passages: lane runs (one-cell passages, doorways) that join two open cells. Each gets an id, its
     * cells a position from one end (A) to the other (B), and its two exits (the open cells beyond A and B).
     */
    private void markThroughLanes() {
        boolean[] seen = new boolean[lane.length];
        int[] run = new int[lane.length];
        List<int[]> exits = new ArrayList<>();
        for (int c = 0; c < lane.length; c++) {
            if (!lane[c] || seen[c] || laneNeighbours(c) > 1) {
                continue; // a run is walked from one of its ends
            }
            int size = 0;
            int prev = -1;
            for (int x = c; x >= 0; ) {
                seen[x] = true;
                run[size++] = x;
                int next = -1;
                for (int n : neighbours[x]) {
                    if (lane[n] && n != prev && !seen[n]) {
                        next = n;
                    }
                }
                prev = x;
                x = next;
            }
            int exitA = openNeighbour(run[0], size > 1 ? run[1] : -1, -1);
            int exitB = openNeighbour(run[size - 1], size > 1 ? run[size - 2] : -1, exitA);
            if (exitA < 0 || exitB < 0 || around(run, size, exitA, exitB)) {
                continue; // a dead end or pocket (a corner too): a place to wait, not a passage
            }
            int id = exits.size();
            exits.add(new int[] {exitA, exitB});
            for (int i = 0; i < size; i++) {
                runOf[run[i]] = id;
                runPos[run[i]] = i;
            }
        }
        runExits = exits.toArray(new int[0][]);
    }

    /**
     * Whether robots can go from one exit of a lane run to the other around it, in at most two steps more than
     * through it: a run along a room's wall or in its corner, not a way between rooms. Taken for a passage, such a
     * run holding a robot's dock or a cart's cell was never entered: waiting on a goal in a passage costs as much
     * as waiting beside it.
     */
    private boolean around(int[] run, int size, int exitA, int exitB) {
        int limit = size + 3;
        Set<Integer> inRun = new HashSet<>();
        for (int i = 0; i < size; i++) {
            inRun.add(run[i]);
        }
        Map<Integer, Integer> steps = new HashMap<>();
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        steps.put(exitA, 0);
        queue.add(exitA);
        while (!queue.isEmpty()) {
            int c = queue.poll();
            int d = steps.get(c);
            if (c == exitB) {
                return true;
            }
            if (d < limit) {
                for (int n : neighbours[c]) {
                    if (!inRun.contains(n) && steps.putIfAbsent(n, d + 1) == null) {
                        queue.add(n);
                    }
                }
            }
        }
        return false;
    }

    private int laneNeighbours(int c) {
        int n = 0;
        for (int x : neighbours[c]) {
            n += lane[x] ? 1 : 0;
        }
        return n;
    }

    /** An open (not lane) neighbour of c other than {@code inside} and {@code not}, or -1. */
    private int openNeighbour(int c, int inside, int not) {
        for (int n : neighbours[c]) {
            if (n != inside && n != not && !lane[n]) {
                return n;
            }
        }
        return -1;
    }

    /** The planner's view of a grid. */
    public static TrafficMap of(Grid grid) {
        return new TrafficMap(grid);
    }

    /** The planner's view of a map in the fleet's text format (rows joined by newlines). */
    public static TrafficMap parse(String rows) {
        return new TrafficMap(Grid.parse(rows));
    }

    public Grid grid() {
        return grid;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int cells() {
        return passable.length;
    }

    public int cell(Cell c) {
        return c.y() * width + c.x();
    }

    public int cell(int x, int y) {
        return y * width + x;
    }

    public Cell cell(int c) {
        return new Cell(c % width, c / width);
    }

    public boolean passable(int c) {
        return passable[c];
    }

    public boolean door(int c) {
        return door[c];
    }

    /** @return whether two robots cannot pass each other in this cell (at most two passable neighbours) */
    public boolean lane(int c) {
        return lane[c];
    }

    /**
     * @return the passage (a lane of one-cell width joining two open cells, or a doorway) the cell belongs to, or -1
     *         (open cells, dead ends and pockets)
     */
    public int passage(int c) {
        return runOf[c];
    }

    /** @return how many passages the map has */
    public int passages() {
        return runExits.length;
    }

    /** @return a passage cell's position counted from the passage's end A */
    int passagePosition(int c) {
        return runPos[c];
    }

    /** @return the open cell beyond end A (side 0) or end B (side 1) of a passage */
    int passageExit(int passage, int side) {
        return runExits[passage][side];
    }

    /** @return whether the cell is the exit of a passage (the open cell beyond one of its ends) */
    boolean passageExit(int c) {
        return exit[c];
    }

    /** The passable neighbours (N, E, S, W order); do not modify the array. */
    int[] neighbours(int c) {
        return neighbours[c];
    }

    /** @return the Manhattan distance between two cells */
    public int manhattan(int a, int b) {
        return Math.abs(a % width - b % width) + Math.abs(a / width - b / width);
    }
}
