package eu.brain.iot.robotsim.world;

import java.util.ArrayList;
import java.util.List;

/**
 * Finds robots that wait on each other in a cycle (A's front sensor sees B, B's sees A, ...) and counts a deadlock
 * once per cycle when it has lasted {@link SimRules#deadlockSteps()} steps. Each robot waits on at most one other,
 * so the wait-for graph is functional and cycles are found in linear time. Owned by the world's owner thread.
 */
final class DeadlockDetector {
    private final int[] walkMark;
    private final boolean[] inCycle;
    private int walk;

    DeadlockDetector(int robots) {
        walkMark = new int[robots];
        inCycle = new boolean[robots];
    }

    void afterStep(World world) {
        Robot[] robots = world.robots;
        List<int[]> cycles = findCycles(robots);
        for (Robot r : robots) {
            if (inCycle[r.index()]) {
                r.cycleSteps++;
            } else {
                r.cycleSteps = 0;
                r.deadlockCounted = false;
            }
        }
        int needed = world.rules.deadlockSteps();
        for (int[] cycle : cycles) {
            boolean ripe = true;
            boolean counted = false;
            for (int i : cycle) {
                ripe &= robots[i].cycleSteps >= needed;
                counted |= robots[i].deadlockCounted;
            }
            if (ripe && !counted) {
                world.deadlocks++;
                for (int i : cycle) {
                    robots[i].deadlocks++;
                    robots[i].deadlockCounted = true;
                }
            }
        }
    }

    private List<int[]> findCycles(Robot[] robots) {
        java.util.Arrays.fill(inCycle, false);
        java.util.Arrays.fill(walkMark, 0);
        List<int[]> cycles = new ArrayList<>();
        walk = 0;
        for (Robot start : robots) {
            if (walkMark[start.index()] != 0 || start.blockedBy < 0) {
                continue;
            }
            walk++;
            int i = start.index();
            while (i >= 0 && walkMark[i] == 0) {
                walkMark[i] = walk;
                i = robots[i].blockedBy;
            }
            if (i >= 0 && walkMark[i] == walk) {
                cycles.add(collect(robots, i));
            }
        }
        return cycles;
    }

    private int[] collect(Robot[] robots, int first) {
        List<Integer> members = new ArrayList<>();
        int i = first;
        do {
            members.add(i);
            inCycle[i] = true;
            i = robots[i].blockedBy;
        } while (i != first);
        return members.stream().mapToInt(Integer::intValue).toArray();
    }
}
