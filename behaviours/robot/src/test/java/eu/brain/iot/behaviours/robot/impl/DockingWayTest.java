package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Set;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * The way in and out of the docking area keeps off other robots' docks: robot-sim's shortest path ran along the
 * docking rows past parked robots (the generated warehouses dock robots on two rows).
 */
class DockingWayTest {

    private static final Grid TWO_ROWS = Grid.parse(String.join("\n",
            "########",
            "#RdRdRd#",
            "#Rddddd#",
            "#......#",
            "#ssssss#",
            "########"));

    @Test
    void robotsEnterAndLeaveTheDockingAreaByTheirOwnColumnAndNeverThroughAnotherRobotsDock() {
        Errands errands = new Errands(6);
        errands.seen("robot1", new Cell(1, 1), true);
        errands.seen("robot2", new Cell(3, 1), true);
        errands.seen("robot3", new Cell(1, 2), true);

        assertThat(edge(errands, "robot2", new Cell(3, 1), Set.of())).isEqualTo(new Cell(3, 3));
        assertThat(edge(errands, "robot3", new Cell(1, 2), Set.of())).isEqualTo(new Cell(1, 3));
        // robot1's own column holds robot3's dock: its way goes round it
        assertThat(edge(errands, "robot1", new Cell(1, 1), Set.of())).isEqualTo(new Cell(2, 3));
        // robot3 parked at (1,2) before its dock was learnt (the first look at the fleet) is kept off too
        Errands first = new Errands(6);
        first.seen("robot1", new Cell(1, 1), true);
        assertThat(edge(first, "robot1", new Cell(1, 1), Set.of(new Cell(1, 2)))).isEqualTo(new Cell(2, 3));
        // a robot sent aside to a docking cell leaves from where it stands
        assertThat(edge(errands, "robot2", new Cell(6, 2), Set.of())).isEqualTo(new Cell(6, 3));

        // robot-sim's own shortest path from (1,1) to (2,3) may run through robot3's dock: the go-to is the first
        // straight leg of a way round it, which robot-sim can only take as it is
        Set<Cell> others = errands.otherDocks("robot1", Set.of());
        assertThat(DockingWay.straightToward(new Cell(1, 1), new Cell(2, 3), TWO_ROWS, others))
                .isEqualTo(new Cell(2, 1));
        assertThat(DockingWay.straightToward(new Cell(2, 1), new Cell(2, 3), TWO_ROWS, others))
                .isEqualTo(new Cell(2, 3));
        assertThat(DockingWay.straightToward(new Cell(2, 3), new Cell(1, 1), TWO_ROWS, others))
                .isEqualTo(new Cell(2, 1));
    }

    @Test
    void aRobotGoingHomeIsSentToWhereItsDockMeetsTheFloorThenInLegByLegAndOutTheSameWay() {
        Set<Cell> others = Set.of(new Cell(3, 1), new Cell(1, 2)); // robot2's and robot3's docks
        Cell dock = new Cell(1, 1);
        // out on the floor, going home: first to the edge of the docking area nearest its dock, round robot3's dock
        assertThat(DockingWay.next(new Cell(5, 4), dock, dock, TWO_ROWS, others)).isEqualTo(new Cell(2, 3));
        // at that edge: the first straight leg in
        assertThat(DockingWay.next(new Cell(2, 3), dock, dock, TWO_ROWS, others)).isEqualTo(new Cell(2, 1));
        assertThat(DockingWay.next(new Cell(2, 1), dock, dock, TWO_ROWS, others)).isEqualTo(dock);
        // leaving its dock for a cart in storage: out to the floor first, the same way
        assertThat(DockingWay.next(dock, new Cell(5, 4), dock, TWO_ROWS, others)).isEqualTo(new Cell(2, 1));
        // a goal on the floor from the floor is robot-sim's to plan
        assertThat(DockingWay.next(new Cell(5, 3), new Cell(5, 4), dock, TWO_ROWS, others)).isEqualTo(new Cell(5, 4));
    }

    @Test
    void aRobotMetOutOnTheFloorGetsTheDockItHadUnlessTakenElseAFreeOneNextToNoOtherDock() {
        Set<Cell> docks = Set.of(new Cell(1, 1));
        assertThat(DockingWay.dockFor(new Cell(5, 3), new Cell(3, 1), docks, docks, TWO_ROWS))
                .as("the dock an earlier run learnt").isEqualTo(new Cell(3, 1));
        Cell given = DockingWay.dockFor(new Cell(1, 3), new Cell(1, 1), docks, docks, TWO_ROWS);
        assertThat(given).as("its old dock is taken: a free cell, next to no taken one").isNotEqualTo(new Cell(1, 1));
        assertThat(TWO_ROWS.area(given)).isEqualTo(Grid.DOCKING);
        assertThat(TWO_ROWS.neighbours(given)).doesNotContain(new Cell(1, 1));
    }

    private static Cell edge(Errands errands, String robot, Cell from, Set<Cell> parked) {
        return DockingWay.edgeOfDocking(from, TWO_ROWS, errands.otherDocks(robot, parked));
    }
}
