package eu.brain.iot.behaviours.warehouse;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

/**
 * The warehouse's terrain, in the fleet's map format (robot-sim's README: {@code #} wall, {@code .} corridor,
 * {@code d} docking, {@code u} unload, {@code s} storage, {@code D} door), and the two searches the behaviours need:
 * a shortest path as a robot plans one (through doors, ignoring robots; the fleet breaks ties its own way, so this
 * is one of the shortest paths, not necessarily the robot's) and the nearest cell that satisfies a condition.
 * Immutable, so any thread may use it.
 */
public final class Grid {

    /** Area codes of the fleet (and of the models where the names exist: inDocking = 1, ...). */
    public static final int CORRIDOR = 0;
    public static final int DOCKING = 1;
    public static final int UNLOAD = 2;
    public static final int STORAGE = 3;
    public static final int DOORWAY = 5;

    private static final int[][] STEPS = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}}; // N, E, S, W

    private final String[] rows;
    private final int width;
    /** Every cell of each area, row by row ({@link #cells}): read for every robot at every look, so found once. */
    private final Map<Integer, List<Cell>> byArea;

    private Grid(String[] rows) {
        this.rows = rows;
        this.width = rows.length == 0 ? 0 : rows[0].length();
        Map<Integer, List<Cell>> found = new HashMap<>();
        for (int y = 0; y < rows.length; y++) {
            for (int x = 0; x < width; x++) {
                Cell c = new Cell(x, y);
                found.computeIfAbsent(area(c), a -> new ArrayList<>()).add(c);
            }
        }
        Map<Integer, List<Cell>> frozen = new HashMap<>();
        found.forEach((area, cells) -> frozen.put(area, List.copyOf(cells)));
        this.byArea = Map.copyOf(frozen);
    }

    /**
     * @param rows the grid's rows, top first, joined by newlines (the edge's {@code warehouse/map/rows})
     * @throws IllegalArgumentException when the rows are empty or not all of one width
     */
    public static Grid parse(String rows) {
        String[] lines = rows == null ? new String[0] : rows.split("\n");
        if (lines.length == 0 || lines[0].isEmpty()) {
            throw new IllegalArgumentException("the warehouse map has no rows");
        }
        for (String line : lines) {
            if (line.length() != lines[0].length()) {
                throw new IllegalArgumentException("the warehouse map's rows are not all " + lines[0].length()
                        + " cells wide: '" + line + "'");
            }
        }
        return new Grid(lines);
    }

    public int width() {
        return width;
    }

    public int height() {
        return rows.length;
    }

    public boolean inside(Cell c) {
        return c.x() >= 0 && c.y() >= 0 && c.x() < width && c.y() < rows.length;
    }

    /** @return whether a robot may stand on or drive through the cell (anything but a wall, inside the map) */
    public boolean passable(Cell c) {
        return inside(c) && rows[c.y()].charAt(c.x()) != '#';
    }

    /** @return the cell's area code (0 corridor, 1 docking, 2 unload, 3 storage, 5 doorway), -1 for a wall */
    public int area(Cell c) {
        if (!passable(c)) {
            return -1;
        }
        return switch (rows[c.y()].charAt(c.x())) {
            case 'd', 'R' -> DOCKING;
            case 'u', 'C' -> UNLOAD;
            case 's' -> STORAGE;
            case 'D' -> DOORWAY;
            default -> CORRIDOR;
        };
    }

    /** @return every cell of an area, row by row, left to right (unmodifiable) */
    public List<Cell> cells(int area) {
        return byArea.getOrDefault(area, List.of());
    }

    /** @return the passable neighbours of a cell, in the order N, E, S, W */
    public List<Cell> neighbours(Cell c) {
        List<Cell> next = new ArrayList<>(4);
        for (int[] s : STEPS) {
            Cell n = new Cell(c.x() + s[0], c.y() + s[1]);
            if (passable(n)) {
                next.add(n);
            }
        }
        return next;
    }

    /**
     * The path a robot plans from one cell to another, avoiding {@code blocked} cells (for a robot carrying a cart:
     * the other carts), both ends excluded from that rule.
     *
     * @return the cells after {@code from} up to {@code to}, empty when {@code from == to}, {@code null} when there
     *         is no path
     */
    public List<Cell> path(Cell from, Cell to, Set<Cell> blocked) {
        if (from.equals(to)) {
            return List.of();
        }
        Cell[][] parent = new Cell[rows.length][width];
        ArrayDeque<Cell> queue = new ArrayDeque<>();
        queue.add(from);
        parent[from.y()][from.x()] = from;
        while (!queue.isEmpty()) {
            Cell c = queue.poll();
            for (Cell n : neighbours(c)) {
                if (parent[n.y()][n.x()] != null || (!n.equals(to) && blocked.contains(n))) {
                    continue;
                }
                parent[n.y()][n.x()] = c;
                if (n.equals(to)) {
                    List<Cell> path = new ArrayList<>();
                    for (Cell p = to; !p.equals(from); p = parent[p.y()][p.x()]) {
                        path.add(p);
                    }
                    Collections.reverse(path);
                    return path;
                }
                queue.add(n);
            }
        }
        return null;
    }

    /**
     * The nearest cell (by steps through cells that are not {@code blocked}) that satisfies {@code wanted}, the
     * start excluded.
     *
     * @return the cell, or {@code null} when none can be reached
     */
    public Cell nearest(Cell from, Predicate<Cell> wanted, Set<Cell> blocked) {
        boolean[][] seen = new boolean[rows.length][width];
        ArrayDeque<Cell> queue = new ArrayDeque<>();
        queue.add(from);
        seen[from.y()][from.x()] = true;
        while (!queue.isEmpty()) {
            Cell c = queue.poll();
            for (Cell n : neighbours(c)) {
                if (seen[n.y()][n.x()] || blocked.contains(n)) {
                    continue;
                }
                seen[n.y()][n.x()] = true;
                if (wanted.test(n)) {
                    return n;
                }
                queue.add(n);
            }
        }
        return null;
    }

    /**
     * @return the steps from {@code from} to every cell reachable from it without entering a {@code blocked} cell
     *         ({@code from} itself at 0)
     */
    public Map<Cell, Integer> distances(Cell from, Set<Cell> blocked) {
        return distances(List.of(from), blocked);
    }

    /**
     * @return the steps to every cell reachable without entering a {@code blocked} cell from the nearest of
     *         {@code from} (each of them at 0)
     */
    public Map<Cell, Integer> distances(List<Cell> from, Set<Cell> blocked) {
        Map<Cell, Integer> dist = new HashMap<>();
        ArrayDeque<Cell> queue = new ArrayDeque<>();
        for (Cell c : from) {
            dist.put(c, 0);
            queue.add(c);
        }
        while (!queue.isEmpty()) {
            Cell x = queue.poll();
            int next = dist.get(x) + 1;
            for (Cell n : neighbours(x)) {
                if (!dist.containsKey(n) && !blocked.contains(n)) {
                    dist.put(n, next);
                    queue.add(n);
                }
            }
        }
        return dist;
    }

    /** @return the length of the shortest path, or {@link Integer#MAX_VALUE} when there is none */
    public int steps(Cell from, Cell to, Set<Cell> blocked) {
        List<Cell> p = path(from, to, blocked);
        return p == null ? Integer.MAX_VALUE : p.size();
    }
}
