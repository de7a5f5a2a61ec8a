package eu.brain.iot.robotsim.world;

import java.util.List;

/**
 * The immutable layout of a warehouse: terrain of every cell and the starting places of robots, carts and doors.
 * Cells are addressed by column x (0 = left) and row y (0 = top); {@code cell = y * width + x}.
 * Instances are shared freely between threads.
 */
public final class WarehouseMap {
    /** Steps a door takes to open when the map does not say. */
    public static final int DEFAULT_DOOR_OPEN_STEPS = 4;

    private final String name;
    private final int width;
    private final int height;
    private final byte[] terrain;
    private final List<Placement> robots;
    private final List<Placement> carts;
    private final List<Placement> doors;
    private final int doorOpenSteps;

    WarehouseMap(String name, int width, int height, byte[] terrain, List<Placement> robots,
                 List<Placement> carts, List<Placement> doors, int doorOpenSteps) {
        this.name = name;
        this.width = width;
        this.height = height;
        this.terrain = terrain.clone();
        this.robots = List.copyOf(robots);
        this.carts = List.copyOf(carts);
        this.doors = List.copyOf(doors);
        this.doorOpenSteps = doorOpenSteps;
    }

    /** The paper's warehouse (section 6.1): 3 robots, 3 carts, one door; shipped as a resource. */
    public static WarehouseMap paper() {
        return MapParser.resource("maps/paper-warehouse.map");
    }

    public String name() {
        return name;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public boolean inside(int x, int y) {
        return x >= 0 && y >= 0 && x < width && y < height;
    }

    /** Terrain at a cell inside the map. */
    public Terrain terrain(int x, int y) {
        return Terrain.ofOrdinal(terrain[y * width + x]);
    }

    Terrain terrain(int cell) {
        return Terrain.ofOrdinal(terrain[cell]);
    }

    public List<Placement> robots() {
        return robots;
    }

    public List<Placement> carts() {
        return carts;
    }

    public List<Placement> doors() {
        return doors;
    }

    public int doorOpenSteps() {
        return doorOpenSteps;
    }

    /** The terrain rows as map-file characters (robots, carts and doors' ids not included). */
    public List<String> terrainRows() {
        String[] rows = new String[height];
        StringBuilder row = new StringBuilder(width);
        for (int y = 0; y < height; y++) {
            row.setLength(0);
            for (int x = 0; x < width; x++) {
                row.append(terrain(x, y).symbol());
            }
            rows[y] = row.toString();
        }
        return List.of(rows);
    }

    /** This map in the map-file format, so that {@link MapParser#parse} gives it back. */
    public String toText() {
        char[][] grid = new char[height][];
        List<String> rows = terrainRows();
        for (int y = 0; y < height; y++) {
            grid[y] = rows.get(y).toCharArray();
        }
        for (Placement r : robots) {
            grid[r.y()][r.x()] = MapParser.ROBOT;
        }
        for (Placement c : carts) {
            grid[c.y()][c.x()] = MapParser.CART;
        }
        StringBuilder out = new StringBuilder();
        out.append("name: ").append(name).append('\n');
        out.append("door-open-steps: ").append(doorOpenSteps).append('\n');
        out.append("map:\n");
        for (char[] line : grid) {
            out.append(line).append('\n');
        }
        return out.toString();
    }
}
