package eu.brain.iot.robotsim.world;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Reads the text map format (documented in robot-sim/README.md):
 * optional header lines ({@code # comment}, {@code name: ...}, {@code door-open-steps: N}), a line {@code map:},
 * then one line per grid row. Robots ({@code R}, on a docking cell), carts ({@code C}, on an unload cell) and
 * doors ({@code D}) get ids robot1.., cart1.., door1.. in reading order (row by row, left to right).
 */
public final class MapParser {
    static final char ROBOT = 'R';
    static final char CART = 'C';
    private static final String LEGEND = "# . d u s D R C";

    private MapParser() {
    }

    public static WarehouseMap parse(Path file) throws MapFormatException, IOException {
        return parse(file.toString(), Files.readString(file, StandardCharsets.UTF_8));
    }

    /** A map shipped on the class path; a broken resource is a bug of this module, so it fails unchecked. */
    public static WarehouseMap resource(String name) {
        try (InputStream in = MapParser.class.getClassLoader().getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("map resource missing: " + name);
            }
            return parse(name, new String(in.readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (MapFormatException e) {
            throw new IllegalStateException(e.getMessage(), e);
        }
    }

    public static WarehouseMap parse(String source, String text) throws MapFormatException {
        String[] lines = text.split("\n", -1);
        String name = source;
        int doorOpenSteps = WarehouseMap.DEFAULT_DOOR_OPEN_STEPS;
        int lineNo = 0;
        boolean gridStarts = false;
        while (lineNo < lines.length) {
            String line = stripCr(lines[lineNo++]).strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            if (line.equals("map:")) {
                gridStarts = true;
                break;
            }
            int colon = line.indexOf(':');
            if (colon < 0) {
                throw new MapFormatException(source, lineNo, 1,
                        "expected a header 'key: value' or the line 'map:' before the grid, found '" + line + "'");
            }
            String key = line.substring(0, colon).strip();
            String value = line.substring(colon + 1).strip();
            switch (key) {
                case "name" -> name = value;
                case "door-open-steps" -> doorOpenSteps = nonNegative(source, lineNo, colon + 2, key, value);
                default -> throw new MapFormatException(source, lineNo, 1,
                        "unknown header '" + key + "' (known: name, door-open-steps)");
            }
        }
        if (!gridStarts) {
            throw new MapFormatException(source, lineNo, 1, "no 'map:' line: the grid must follow a line 'map:'");
        }
        List<String> rows = new ArrayList<>();
        int firstRowLine = lineNo + 1;
        while (lineNo < lines.length) {
            rows.add(stripCr(lines[lineNo++]));
        }
        while (!rows.isEmpty() && rows.get(rows.size() - 1).isBlank()) {
            rows.remove(rows.size() - 1);
        }
        if (rows.isEmpty()) {
            throw new MapFormatException(source, firstRowLine, 1, "the grid after 'map:' is empty");
        }
        return grid(source, name, doorOpenSteps, rows, firstRowLine);
    }

    private static WarehouseMap grid(String source, String name, int doorOpenSteps, List<String> rows,
                                     int firstRowLine) throws MapFormatException {
        int width = rows.get(0).length();
        int height = rows.size();
        byte[] terrain = new byte[width * height];
        List<Placement> robots = new ArrayList<>();
        List<Placement> carts = new ArrayList<>();
        List<Placement> doors = new ArrayList<>();
        for (int y = 0; y < height; y++) {
            String row = rows.get(y);
            int line = firstRowLine + y;
            if (row.length() != width) {
                throw new MapFormatException(source, line, Math.min(row.length(), width) + 1,
                        "row has " + row.length() + " cells but the first row has " + width
                                + "; every row must have the same width");
            }
            for (int x = 0; x < width; x++) {
                char c = row.charAt(x);
                Terrain t = switch (c) {
                    case ROBOT -> {
                        robots.add(new Placement("robot" + (robots.size() + 1), x, y));
                        yield Terrain.DOCKING;
                    }
                    case CART -> {
                        carts.add(new Placement("cart" + (carts.size() + 1), x, y));
                        yield Terrain.UNLOAD;
                    }
                    default -> terrainOf(c);
                };
                if (t == null) {
                    throw new MapFormatException(source, line, x + 1,
                            "unknown cell '" + c + "' (expected one of " + LEGEND + ")");
                }
                if (t == Terrain.DOOR) {
                    doors.add(new Placement("door" + (doors.size() + 1), x, y));
                }
                terrain[y * width + x] = (byte) t.ordinal();
            }
        }
        return new WarehouseMap(name, width, height, terrain, robots, carts, doors, doorOpenSteps);
    }

    private static Terrain terrainOf(char c) {
        for (Terrain t : Terrain.values()) {
            if (t.symbol() == c) {
                return t;
            }
        }
        return null;
    }

    private static int nonNegative(String source, int line, int col, String key, String value)
            throws MapFormatException {
        try {
            int n = Integer.parseInt(value);
            if (n >= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new MapFormatException(source, line, col, key + " must be a whole number >= 0, found '" + value + "'");
    }

    private static String stripCr(String s) {
        return s.endsWith("\r") ? s.substring(0, s.length() - 1) : s;
    }
}
