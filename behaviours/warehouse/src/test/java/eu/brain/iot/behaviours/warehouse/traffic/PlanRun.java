package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntUnaryOperator;

/**
 * Runs a planner step by step on its own plan (each robot moves to its planned cell of step 1) and checks every
 * round against robot-sim's rules: no two robots in one cell, no robot entering a cell that was occupied at the
 * start of the step, every move to a neighbour or a wait. Test helper.
 */
final class PlanRun {
    final FleetPlanner planner;
    final TrafficMap map;
    final int[] at;
    final int[] goal;
    final boolean[] offline;
    final List<String> violations = new ArrayList<>();
    int steps;

    PlanRun(String rows, int window, int... robotCells) {
        map = TrafficMap.parse(rows);
        planner = new FleetPlanner(map, robotCells.length, window);
        at = robotCells.clone();
        goal = new int[at.length];
        java.util.Arrays.fill(goal, FleetPlanner.NO_GOAL);
        offline = new boolean[at.length];
    }

    int cell(int x, int y) {
        return map.cell(x, y);
    }

    /** Plans and moves one step; checks the whole window's plan and the move. */
    void step() {
        for (int r = 0; r < at.length; r++) {
            planner.robot(r, at[r], goal[r], false, offline[r]);
        }
        planner.plan();
        checkPlan();
        int[] before = at.clone();
        for (int r = 0; r < at.length; r++) {
            if (!offline[r]) {
                at[r] = planner.path(r)[1];
            }
        }
        for (int r = 0; r < at.length; r++) {
            if (at[r] != before[r]) {
                boolean adjacent = map.manhattan(at[r], before[r]) == 1;
                if (!adjacent) {
                    violations.add("step " + steps + ": robot " + r + " jumped " + map.cell(before[r]) + " -> "
                            + map.cell(at[r]));
                }
                for (int o = 0; o < at.length; o++) {
                    if (o != r && before[o] == at[r]) {
                        violations.add("step " + steps + ": robot " + r + " entered " + map.cell(at[r])
                                + " that robot " + o + " stood in");
                    }
                }
            }
        }
        steps++;
    }

    /** Steps until every robot is at its goal (or the limit); each robot's next goal from {@code next} on arrival. */
    int runUntil(int limit, IntUnaryOperator nextGoal) {
        for (int s = 0; s < limit; s++) {
            boolean all = true;
            for (int r = 0; r < at.length; r++) {
                if (goal[r] != FleetPlanner.NO_GOAL && at[r] == goal[r]) {
                    goal[r] = nextGoal.applyAsInt(r);
                }
                all &= goal[r] == FleetPlanner.NO_GOAL || offline[r];
            }
            if (all) {
                return s;
            }
            step();
        }
        return -1;
    }

    private void checkPlan() {
        int w = planner.window();
        for (int a = 0; a < at.length; a++) {
            int[] pa = planner.path(a);
            if (pa[0] != at[a]) {
                violations.add("step " + steps + ": robot " + a + "'s plan starts at " + map.cell(pa[0]));
            }
            for (int t = 1; t <= w; t++) {
                if (pa[t] != pa[t - 1] && map.manhattan(pa[t], pa[t - 1]) != 1) {
                    violations.add("step " + steps + ": robot " + a + " plans a jump at " + t);
                }
            }
            for (int b = a + 1; b < at.length; b++) {
                int[] pb = planner.path(b);
                for (int t = 0; t <= w; t++) {
                    for (int s = Math.max(0, t - 1); s <= Math.min(w, t + 1); s++) {
                        if (pa[t] == pb[s]) {
                            violations.add("step " + steps + ": robots " + a + " and " + b + " both plan "
                                    + map.cell(pa[t]) + " at steps " + t + " and " + s);
                        }
                    }
                }
            }
        }
    }
}
