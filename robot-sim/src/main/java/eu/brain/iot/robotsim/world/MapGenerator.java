package eu.brain.iot.robotsim.world;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

/**
 * Generates large warehouses with the paper's structure, top to bottom: docking rows (robots on every other column,
 * so each can leave sideways), a corridor, the storage area, a corridor, a wall with evenly spaced doors, and the
 * unload area where carts stand densely in 2x2 blocks between one-cell aisles (every cart touches an aisle, and the
 * row behind the doors is an aisle). Which cart slots are filled depends on the seed only.
 */
public final class MapGenerator {
    private static final int CORRIDOR_ROWS = 2;

    private MapGenerator() {
    }

    /** The layout the generator would make, as text in the map format. */
    public static String text(String name, int width, int height, int robots, int carts, int doors, long seed) {
        if (width < 7 || height < 12) {
            throw new IllegalArgumentException("a generated warehouse needs at least 7x12 cells, asked "
                    + width + "x" + height);
        }
        if (robots < 0 || carts < 0 || doors < 1) {
            throw new IllegalArgumentException("robots and carts must be >= 0 and doors >= 1");
        }
        int inner = width - 2;
        int robotsPerRow = (inner + 1) / 2;
        int dockRows = Math.max(1, (robots + robotsPerRow - 1) / robotsPerRow);
        int fixedRows = 2 + dockRows + 2 * CORRIDOR_ROWS + 1;
        int free = height - fixedRows;
        int storageRows = Math.max(2, free / 4);
        int unloadRows = free - storageRows;
        if (unloadRows < 3) {
            throw new IllegalArgumentException(robots + " robots need " + dockRows + " docking rows; "
                    + height + " rows leave no room for storage and unload areas: make the map taller");
        }
        if (doors > inner / 2) {
            throw new IllegalArgumentException(doors + " doors do not fit in a " + inner + "-cell wall");
        }
        char[][] grid = new char[height][width];
        for (char[] row : grid) {
            java.util.Arrays.fill(row, '#');
        }
        int y = 1;
        int placed = 0;
        for (int r = 0; r < dockRows; r++, y++) {
            for (int x = 1; x <= inner; x++) {
                boolean slot = (x - 1) % 2 == 0 && placed < robots;
                grid[y][x] = slot ? 'R' : 'd';
                placed += slot ? 1 : 0;
            }
        }
        y = fill(grid, y, CORRIDOR_ROWS, '.');
        y = fill(grid, y, storageRows, 's');
        y = fill(grid, y, CORRIDOR_ROWS, '.');
        int wallRow = y++;
        for (int d = 0; d < doors; d++) {
            int x = 1 + (int) ((d + 0.5) * inner / doors);
            grid[wallRow][x] = 'D';
        }
        int unloadTop = y;
        List<int[]> slots = new ArrayList<>();
        for (int r = 0; r < unloadRows; r++, y++) {
            for (int x = 1; x <= inner; x++) {
                grid[y][x] = 'u';
                if ((x - 1) % 3 != 0 && r % 3 != 0) {
                    slots.add(new int[] {x, y});
                }
            }
        }
        if (carts > slots.size()) {
            throw new IllegalArgumentException(carts + " carts do not fit: the unload area ("
                    + inner + "x" + unloadRows + " from row " + unloadTop + ") has " + slots.size()
                    + " cart slots; make the map larger");
        }
        Collections.shuffle(slots, new Random(seed));
        for (int i = 0; i < carts; i++) {
            int[] s = slots.get(i);
            grid[s[1]][s[0]] = 'C';
        }
        StringBuilder out = new StringBuilder();
        out.append("# generated: ").append(width).append('x').append(height).append(", ").append(robots)
                .append(" robots, ").append(carts).append(" carts, ").append(doors).append(" doors, seed ")
                .append(seed).append('\n');
        out.append("name: ").append(name).append('\n');
        out.append("door-open-steps: ").append(WarehouseMap.DEFAULT_DOOR_OPEN_STEPS).append('\n');
        out.append("map:\n");
        for (char[] row : grid) {
            out.append(row).append('\n');
        }
        return out.toString();
    }

    /** The generated layout, parsed. */
    public static WarehouseMap generate(int width, int height, int robots, int carts, int doors, long seed) {
        String name = "generated-" + width + "x" + height + "-" + robots + "r";
        try {
            return MapParser.parse(name, text(name, width, height, robots, carts, doors, seed));
        } catch (MapFormatException e) {
            throw new IllegalStateException("generator produced an unreadable map: " + e.getMessage(), e);
        }
    }

    private static int fill(char[][] grid, int y, int rows, char c) {
        for (int r = 0; r < rows; r++, y++) {
            for (int x = 1; x < grid[y].length - 1; x++) {
                grid[y][x] = c;
            }
        }
        return y;
    }
}
