package eu.brain.iot.behaviours.warehouse.traffic;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** A doorway crossed in batches, one direction at a time, the batch sized to the queue. */
class DoorBatchesTest {

    private static final String ROOMS = FleetPlannerTest.TWO_ROOMS;

    private final TrafficMap map = TrafficMap.parse(ROOMS);
    private final Distances distances = new Distances(map, 16);

    private int cell(int x, int y) {
        return map.cell(x, y);
    }

    /** @return the side of the doorway a cell is on: that of the exit it is nearer */
    private int sideOf(int c) {
        int p = map.passage(cell(4, 3));
        return map.manhattan(c, map.passageExit(p, 0)) <= map.manhattan(c, map.passageExit(p, 1)) ? 0 : 1;
    }

    @Test
    void theLongerQueueGoesFirstThenTheDoorTurnsOnceItsRobotsCrossed() {
        DoorBatches doors = new DoorBatches(map, 3);
        assertThat(doors.doorways()).isEqualTo(1);
        int[] cell = { cell(3, 2), cell(5, 2), cell(4, 4) };
        int[] goal = { cell(3, 5), cell(5, 5), cell(4, 1) };

        int[] rank = doors.ranks(cell, goal, distances);
        assertThat(rank).as("two above, one below: the two go first").containsExactly(DoorBatches.IN_BATCH,
                DoorBatches.IN_BATCH, 0);
        assertThat(doors.side(0)).isEqualTo(sideOf(cell(3, 2)));

        cell[0] = cell(3, 5); // crossed
        assertThat(doors.ranks(cell, goal, distances)).containsExactly(0, DoorBatches.IN_BATCH, 0);
        cell[1] = cell(4, 3); // in the doorway: off the queue, driving through
        assertThat(doors.ranks(cell, goal, distances)).as("the door turns to the robot below")
                .containsExactly(0, 0, DoorBatches.IN_BATCH);
        assertThat(doors.side(0)).isEqualTo(sideOf(cell(4, 4)));
    }

    @Test
    void aBatchWhoseRobotsDoNotCrossEndsAfterItsRoundsAndTheOtherSideGoes() {
        DoorBatches doors = new DoorBatches(map, 2);
        int[] cell = { cell(4, 2), cell(4, 4) };
        int[] goal = { cell(4, 5), cell(4, 1) };
        int rounds = DoorBatches.ROUNDS_PER_ROBOT + DoorBatches.SLACK_ROUNDS;
        List<Integer> first = new ArrayList<>();
        for (int round = 0; round < rounds; round++) {
            int[] rank = doors.ranks(cell, goal, distances);
            first.add(rank[0] == DoorBatches.IN_BATCH ? 0 : 1);
        }
        assertThat(first).as("one robot each side, neither moves: the batch has its rounds").containsOnly(
                first.get(0));
        int[] rank = doors.ranks(cell, goal, distances);
        assertThat(rank[first.get(0)]).as("then the door turns").isZero();
        assertThat(rank[1 - first.get(0)]).isEqualTo(DoorBatches.IN_BATCH);
    }

    @Test
    void onlyRobotsNearTheDoorWhoseWayGoesThroughItQueue() {
        String wide = String.join("\n",
                "##################",
                "#................#",
                "#................#",
                "####D#############",
                "#................#",
                "##################");
        TrafficMap m = TrafficMap.parse(wide);
        DoorBatches doors = new DoorBatches(m, 3);
        int[] cell = { m.cell(3, 2), m.cell(15, 2), m.cell(5, 1) };
        int[] goal = { m.cell(1, 1), m.cell(15, 4), FleetPlanner.NO_GOAL };
        assertThat(doors.ranks(cell, goal, new Distances(m, 4))).as("its goal this side; too far; no goal")
                .containsOnly(0);
    }

    /** Four robots each way: the doorway changes direction a few times, not at every robot. */
    @Test
    void queuesOnBothSidesCrossInBatchesNotRobotByRobot() {
        int[] start = new int[8];
        for (int i = 0; i < 4; i++) {
            start[i] = cell(2 + i, 1);
            start[4 + i] = cell(2 + i, 5);
        }
        PlanRun run = new PlanRun(ROOMS, 12, start);
        for (int i = 0; i < 4; i++) {
            run.goal[i] = cell(2 + i, 5);
            run.goal[4 + i] = cell(2 + i, 1);
        }
        int door = cell(4, 3);
        List<Integer> crossings = new ArrayList<>();
        for (int s = 0; s < 120 && crossings.size() < 8; s++) {
            int[] before = run.at.clone();
            run.step();
            for (int r = 0; r < 8; r++) {
                if (before[r] == door && run.at[r] != door) {
                    crossings.add(r < 4 ? 0 : 1);
                }
            }
        }
        assertThat(run.violations).isEmpty();
        assertThat(crossings).hasSize(8);
        int turns = 0;
        for (int i = 1; i < crossings.size(); i++) {
            turns += crossings.get(i).equals(crossings.get(i - 1)) ? 0 : 1;
        }
        assertThat(turns).as("directions in order of crossing: " + crossings).isLessThanOrEqualTo(2);
    }
}
