package eu.brain.iot.behaviours.robot.impl;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.CRC32;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * The docks the robot behaviour learnt (the docking cell each robot was first seen on), kept in the bundle's own
 * data area so that the behaviour started again (stopped while the fleet works, brought back by the BMS) sends every
 * robot home to the dock it left from, not to the nearest free docking cell: robots parked next to each other at the
 * edge of the docking area would stand in each other's way in and out, for ever. The book is for one warehouse: its first
 * line names the map (a checksum of its areas), and a book of another map is not read.
 * <p>
 * File format ({@code docks.tsv}): {@code map <checksum>}, then {@code <robot> <x> <y>} per line.
 * <p>
 * Thread-safe: every method is {@code synchronized}.
 */
final class DockBook {

    private static final System.Logger LOG = System.getLogger(DockBook.class.getName());

    /** Where the book is kept; {@code null}: nowhere (no data area), nothing is kept. */
    private final Path file;
    private Map<String, Cell> saved = Map.of();

    DockBook(Path file) {
        this.file = file;
    }

    /** @return the docks kept for this map, none when the book is of another map, missing or unreadable */
    synchronized Map<String, Cell> load(Grid grid) {
        if (file == null || !Files.exists(file)) {
            return Map.of();
        }
        try {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            if (lines.isEmpty() || !lines.get(0).equals("map " + checksum(grid))) {
                return Map.of();
            }
            Map<String, Cell> docks = new HashMap<>();
            for (String line : lines.subList(1, lines.size())) {
                String[] f = line.split(" ");
                if (f.length == 3 && f[1].matches("\\d{1,6}") && f[2].matches("\\d{1,6}")) {
                    Cell c = new Cell(Integer.parseInt(f[1]), Integer.parseInt(f[2]));
                    if (grid.inside(c) && grid.area(c) == Grid.DOCKING) {
                        docks.put(f[0], c);
                    }
                }
            }
            saved = Map.copyOf(docks);
            return saved;
        } catch (IOException | RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "the robots'' docks kept in {0} cannot be read ({1}): docks are "
                    + "learnt again", file, e.getMessage());
            return Map.of();
        }
    }

    /** Keeps the docks when they changed since last kept; a failure is logged, never thrown. */
    synchronized void save(Grid grid, Map<String, Cell> docks) {
        if (file == null || docks.equals(saved)) {
            return;
        }
        StringBuilder text = new StringBuilder("map ").append(checksum(grid)).append('\n');
        new TreeMap<>(docks).forEach((robot, c) -> text.append(robot).append(' ').append(c.x()).append(' ')
                .append(c.y()).append('\n'));
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
            Files.writeString(tmp, text, StandardCharsets.UTF_8);
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            saved = Map.copyOf(docks);
        } catch (IOException | RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "the robots'' docks cannot be kept in {0} ({1}): a behaviour "
                    + "started again learns them anew", file, e.getMessage());
        }
    }

    /** A checksum of the map's size and every cell's area. */
    static String checksum(Grid grid) {
        CRC32 crc = new CRC32();
        crc.update(grid.width());
        crc.update(grid.height());
        for (int y = 0; y < grid.height(); y++) {
            for (int x = 0; x < grid.width(); x++) {
                Cell c = new Cell(x, y);
                crc.update(grid.passable(c) ? grid.area(c) : 0xFF);
            }
        }
        return Long.toHexString(crc.getValue());
    }
}
