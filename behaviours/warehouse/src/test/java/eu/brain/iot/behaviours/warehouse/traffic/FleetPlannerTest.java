package eu.brain.iot.behaviours.warehouse.traffic;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;

import org.junit.jupiter.api.Test;

class FleetPlannerTest {

    /** A small warehouse of the generator's kind: docks, storage, a wall with one door, the unload area. */
    static final String SMALL = String.join("\n",
            "############",
            "#dddddddddd#",
            "#..........#",
            "#ssssssssss#",
            "#..........#",
            "#####D######",
            "#uuuuuuuuuu#",
            "#uuuuuuuuuu#",
            "############");

    @Test
    void reservationsNeverOverlapInSpaceTimeAndEveryRobotKeepsDelivering() {
        int robots = 10;
        int[] start = new int[robots];
        TrafficMap map = TrafficMap.parse(SMALL);
        for (int r = 0; r < robots; r++) {
            start[r] = map.cell(1 + r, 1);
        }
        PlanRun run = new PlanRun(SMALL, 12, start);
        Random random = new Random(7);
        int[] reached = new int[robots];
        for (int r = 0; r < robots; r++) {
            run.goal[r] = randomCell(map, random, r % 2 == 0 ? 7 : 3);
        }
        run.runUntil(600, r -> {
            reached[r]++;
            // errands through the door and back: unload rows (6-7) and storage (row 3) in turn
            int row = map.cell(run.at[r]) .y() >= 6 ? 3 : 7;
            return randomCell(map, random, row);
        });
        assertThat(run.violations).isEmpty();
        for (int r = 0; r < robots; r++) {
            assertThat(reached[r]).as("goals reached by robot " + r).isGreaterThanOrEqualTo(5);
        }
    }

    private static int randomCell(TrafficMap map, Random random, int row) {
        return map.cell(1 + random.nextInt(10), row);
    }

    @Test
    void aRobotWhoseDockOrCartIsInARoomsCornerEntersIt() {
        TrafficMap map = TrafficMap.parse(SMALL);
        assertThat(map.passages()).as("the door only: a corner is no passage").isEqualTo(1);
        PlanRun run = new PlanRun(SMALL, 12, map.cell(1, 2), map.cell(9, 6));
        run.goal[0] = run.cell(1, 1); // the dock in the docking area's corner, from the cell below it
        run.goal[1] = run.cell(10, 7); // a cart in the unload area's corner
        int steps = run.runUntil(40, r -> FleetPlanner.NO_GOAL);
        assertThat(run.violations).isEmpty();
        assertThat(steps).as("steps until both stand at their goals").isBetween(1, 10);
    }

    /**
     * Robots drive straight legs and stop at every corner (robot-sim ends a go-to in the step after the robot
     * arrives): of the shortest ways across a floor strewn with pillars, the planner takes one with two corners (it
     * took one with six while a corner cost nothing).
     */
    @Test
    void aRobotCrossingAFloorOfPillarsTakesAWayWithFewCorners() {
        String floor = String.join("\n",
                "############",
                "#.....#....#",
                "#.#.#...#..#",
                "#...#...#..#",
                "#.#...#....#",
                "##..#......#",
                "#..#.......#",
                "############");
        TrafficMap map = TrafficMap.parse(floor);
        FleetPlanner planner = new FleetPlanner(map, 1, 16);
        planner.robot(0, map.cell(1, 1), map.cell(10, 6), false, false);
        planner.plan();
        int[] path = planner.path(0);
        int corners = 0;
        int last = 0;
        for (int t = 1; t < path.length; t++) {
            int move = path[t] - path[t - 1];
            if (move != 0 && last != 0 && move != last) {
                corners++;
            }
            last = move == 0 ? last : move;
        }
        assertThat(path[path.length - 1]).as("at its goal within the window").isEqualTo(map.cell(10, 6));
        assertThat(corners).isLessThanOrEqualTo(2);
    }

    @Test
    void twoRobotsMeetingHeadOnInACorridorPassUsingAPocket() {
        String corridor = String.join("\n",
                "#########",
                "#.......#",
                "####.####",
                "#########");
        PlanRun run = new PlanRun(corridor, 12, 0, 0);
        run.at[0] = run.cell(1, 1);
        run.at[1] = run.cell(7, 1);
        run.goal[0] = run.cell(7, 1);
        run.goal[1] = run.cell(1, 1);
        int steps = run.runUntil(60, r -> FleetPlanner.NO_GOAL);
        assertThat(run.violations).isEmpty();
        assertThat(steps).as("steps until both swapped ends").isBetween(6, 30);
    }

    /** Two rooms joined by a door. */
    static final String TWO_ROOMS = String.join("\n",
            "#########",
            "#.......#",
            "#.......#",
            "####D####",
            "#.......#",
            "#.......#",
            "#########");

    @Test
    void aDoorIsCrossedBothWaysByQueues() {
        String rows = TWO_ROOMS;
        TrafficMap map = TrafficMap.parse(rows);
        int[] start = new int[8];
        for (int i = 0; i < 4; i++) {
            start[i] = map.cell(2 + i, 1);
            start[4 + i] = map.cell(2 + i, 5);
        }
        PlanRun run = new PlanRun(rows, 12, start);
        for (int i = 0; i < 4; i++) {
            run.goal[i] = map.cell(2 + i, 5);
            run.goal[4 + i] = map.cell(2 + i, 1);
        }
        int steps = run.runUntil(200, r -> FleetPlanner.NO_GOAL);
        assertThat(run.violations).isEmpty();
        assertThat(steps).as("steps until all eight crossed").isPositive().isLessThan(80);
    }

    @Test
    void aRobotOfflineInsideTheDoorIsRoutedAroundUntilItComesBack() {
        String rows = String.join("\n",
                "#######",
                "#.....#",
                "###D###",
                "#.....#",
                "#######");
        TrafficMap map = TrafficMap.parse(rows);
        PlanRun run = new PlanRun(rows, 8, map.cell(3, 2), map.cell(1, 1), map.cell(5, 3));
        run.offline[0] = true;
        run.goal[1] = map.cell(1, 3);
        run.goal[2] = map.cell(5, 1);
        for (int s = 0; s < 30; s++) {
            run.step();
            assertThat(run.at[1]).isNotEqualTo(map.cell(3, 2));
            assertThat(run.at[2]).isNotEqualTo(map.cell(3, 2));
        }
        assertThat(run.at[0]).as("the offline robot stays").isEqualTo(map.cell(3, 2));
        assertThat(run.planner.held(0)).isTrue();
        run.offline[0] = false;
        run.goal[0] = map.cell(4, 3);
        int steps = run.runUntil(80, r -> FleetPlanner.NO_GOAL);
        assertThat(run.violations).isEmpty();
        assertThat(steps).as("all through once it is back").isPositive();
    }

    @Test
    void aRobotGoingOutMeetsOneComingBackInASingleLaneAndBothComplete() {
        assertThat(corridorTrips(1)).as("steps until both went out and came back").isPositive();
    }

    @Test
    void robotsGoingOutMeetRobotsComingBackInASingleLaneAndAllComplete() {
        assertThat(corridorTrips(2)).as("steps until every robot went out and came back").isPositive();
    }

    private static int corridorTrips(int pairs) {
        // the itests' corridor: one lane with a pocket below it every six cells
        String lane = String.join("\n",
                "###############################",
                "#.............................#",
                "######.#####.#####.#####.######",
                "###############################");
        TrafficMap map = TrafficMap.parse(lane);
        assertThat(MapCheck.refusal(map, 16)).isEmpty();
        int[] start = new int[2 * pairs];
        for (int i = 0; i < pairs; i++) {
            start[i] = map.cell(1 + i, 1);
            start[pairs + i] = map.cell(29 - i, 1);
        }
        PlanRun run = new PlanRun(lane, 16, start);
        int[] trips = new int[start.length];
        for (int i = 0; i < pairs; i++) {
            run.goal[i] = map.cell(29 - i, 1);
            run.goal[pairs + i] = map.cell(1 + i, 1);
        }
        int steps = run.runUntil(400, r -> trips[r]++ < 1 ? start[r] : FleetPlanner.NO_GOAL);
        assertThat(run.violations).isEmpty();
        return steps;
    }

    @Test
    void aRobotBoxedInIsHeldAndNobodyIsPlannedThroughIt() {
        String rows = String.join("\n",
                "#####",
                "#...#",
                "#####");
        TrafficMap map = TrafficMap.parse(rows);
        PlanRun run = new PlanRun(rows, 4, map.cell(1, 1), map.cell(2, 1), map.cell(3, 1));
        run.goal[0] = map.cell(3, 1);
        run.goal[2] = map.cell(1, 1);
        for (int s = 0; s < 10; s++) {
            run.step();
        }
        assertThat(run.violations).isEmpty();
        assertThat(run.at).containsExactly(map.cell(1, 1), map.cell(2, 1), map.cell(3, 1));
    }

    @Test
    @org.junit.jupiter.api.Timeout(10)
    void twoRobotsSeenInOneCellAndBoxedInStillGetAPlan() {
        // a stale position: the fleet's view can show two robots in one cell for a poll
        String rows = String.join("\n",
                "#####",
                "#...#",
                "#####");
        TrafficMap map = TrafficMap.parse(rows);
        FleetPlanner planner = new FleetPlanner(map, 4, 4);
        planner.robot(0, map.cell(1, 1), map.cell(3, 1), false, false);
        planner.robot(1, map.cell(1, 1), map.cell(3, 1), false, false);
        planner.robot(2, map.cell(2, 1), map.cell(1, 1), false, false);
        planner.robot(3, map.cell(3, 1), map.cell(1, 1), false, false);
        planner.plan();
        assertThat(planner.path(2)[1]).isEqualTo(map.cell(2, 1));
    }

    /** A round's search work in a packed room: far below what learning unpushable robots one retry at a time took. */
    private static final long MAX_EXPANSIONS_PER_ROUND = 400_000;

    @Test
    void aRoomPackedWithRobotsIsPlannedWithBoundedWork() {
        // 36 of 40 cells taken, everyone bound for the far side of the door: chains of pushes six deep
        String rows = String.join("\n",
                "############",
                "#..........#",
                "#..........#",
                "#..........#",
                "#..........#",
                "#####D######",
                "#..........#",
                "#..........#",
                "############");
        TrafficMap map = TrafficMap.parse(rows);
        int[] start = new int[36];
        for (int r = 0; r < start.length; r++) {
            start[r] = map.cell(1 + r % 10, 1 + r / 10);
        }
        PlanRun run = new PlanRun(rows, 16, start);
        long worst = 0;
        for (int s = 0; s < 60; s++) {
            for (int r = 0; r < start.length; r++) {
                run.goal[r] = map.cell(1 + r % 10, 6 + (r / 10) % 2);
            }
            long before = run.planner.expansions();
            run.step();
            worst = Math.max(worst, run.planner.expansions() - before);
        }
        assertThat(run.violations).isEmpty();
        assertThat(worst).as("search nodes expanded in the costliest round").isLessThan(MAX_EXPANSIONS_PER_ROUND);
    }
}
