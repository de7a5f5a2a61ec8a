package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/** The docks kept for a behaviour started again: for the same map only, and never at the cost of the run. */
class DockBookTest {

    @TempDir
    Path dir;

    static final Grid OTHER = Grid.parse(String.join("\n", "######", "#dddd#", "#....#", "#ssss#", "######"));

    @Test
    void theDocksKeptAreReadBackForTheSameMapOnly() {
        Path file = dir.resolve("docks.tsv");
        Map<String, Cell> docks = Map.of("robot1", new Cell(2, 1), "robot2", new Cell(4, 1));
        new DockBook(file).save(ErrandsTest.PAPER, docks);

        assertThat(new DockBook(file).load(ErrandsTest.PAPER)).isEqualTo(docks);
        assertThat(new DockBook(file).load(OTHER)).as("a book of another warehouse").isEmpty();
    }

    @Test
    void aDamagedBookOrNoneGivesNoDocksAndCellsOutsideTheDockingAreaAreDropped() throws Exception {
        Path file = dir.resolve("docks.tsv");
        assertThat(new DockBook(file).load(ErrandsTest.PAPER)).as("no book yet").isEmpty();
        assertThat(new DockBook(null).load(ErrandsTest.PAPER)).as("no data area").isEmpty();
        Files.writeString(file, "map " + DockBook.checksum(ErrandsTest.PAPER)
                + "\nrobot1 2 1\nrobot2 12 1\nrobot3 x y\n\ngarbage\n");
        assertThat(new DockBook(file).load(ErrandsTest.PAPER)).containsExactly(Map.entry("robot1", new Cell(2, 1)));
    }

    @Test
    void aBookThatCannotBeWrittenIsLoggedNotThrown() throws Exception {
        Path blocker = dir.resolve("file");
        Files.writeString(blocker, "");
        new DockBook(blocker.resolve("docks.tsv")).save(ErrandsTest.PAPER, Map.of("robot1", new Cell(2, 1)));
        assertThat(blocker).isRegularFile();
    }
}
