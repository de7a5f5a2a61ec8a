package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.IntStream;

/**
 * The door policy under the planner: a doorway is crossed in batches, one direction at a time. A robot queues at a
 * doorway when it stands within {@link #QUEUE_STEPS} of one of its exits, nearer that exit than the other, and its
 * shortest way to its goal goes through the doorway from there. When the door turns to a side, the robots queued
 * there form its batch (the nearest {@link #MAX_BATCH} at most: sized to the queue), and they go first in the
 * planner's order ({@link #ranks}) until each has crossed or left the queue, or the batch has had
 * {@link #ROUNDS_PER_ROBOT} rounds per robot plus {@link #SLACK_ROUNDS}; then the door turns to the other side if
 * robots wait there, else a new batch forms on the same side. Without batches the planner's order goes to the robot
 * that waited longest, which at a door alternates the directions robot by robot: each change of direction leaves the
 * doorway empty while the last robot clears it and the first of the other side comes in.
 * <p>
 * Why nobody waits for ever: a batch ends after a bounded number of rounds whatever happens to its robots, and the
 * door then turns to the other side whenever a robot waits there, so a queued robot is in a batch after at most two
 * batches of the other side and one of its own; within its batch the planner's usual order (the longest without
 * progress first) applies.
 * <p>
 * Owned by the planner's thread (not thread-safe).
 */
final class DoorBatches {
    /** How near an exit of a doorway (Manhattan steps) a robot queues at it. */
    static final int QUEUE_STEPS = 6;
    /** Robots in one batch, at most. */
    static final int MAX_BATCH = 8;
    /** Rounds a batch has per robot in it before the door turns anyway. */
    static final int ROUNDS_PER_ROBOT = 3;
    /** Rounds a batch has beyond those per robot. */
    static final int SLACK_ROUNDS = 6;
    /** The rank of a robot in a batch; every other robot's is 0. */
    static final int IN_BATCH = 1;

    private final TrafficMap map;
    /** The doorways: passages holding a door cell. */
    private final int[] doorways;
    /** Per doorway, the side its batch comes from, or -1. */
    private final int[] open;
    /** Per doorway, the robots of its batch. */
    private final List<List<Integer>> batch = new ArrayList<>();
    /** Per doorway, rounds its batch has left. */
    private final int[] roundsLeft;
    private final int[] rank;

    DoorBatches(TrafficMap map, int robots) {
        this.map = map;
        boolean[] isDoorway = new boolean[map.passages()];
        for (int c = 0; c < map.cells(); c++) {
            if (map.door(c) && map.passage(c) >= 0) {
                isDoorway[map.passage(c)] = true;
            }
        }
        this.doorways = IntStream.range(0, isDoorway.length).filter(p -> isDoorway[p]).toArray();
        this.open = new int[doorways.length];
        Arrays.fill(open, -1);
        this.roundsLeft = new int[doorways.length];
        for (int i = 0; i < doorways.length; i++) {
            batch.add(new ArrayList<>());
        }
        this.rank = new int[robots];
    }

    /**
     * One round: the queues seen now, the batches moved on.
     *
     * @param cell      each robot's cell (-1: not placed)
     * @param goal      each robot's goal cell ({@link FleetPlanner#NO_GOAL}: none)
     * @param distances distances to the goals
     * @return each robot's rank: {@link #IN_BATCH} for the robots of a door's batch, else 0 (do not modify)
     */
    int[] ranks(int[] cell, int[] goal, Distances distances) {
        Arrays.fill(rank, 0);
        for (int i = 0; i < doorways.length; i++) {
            List<List<Integer>> queues = queues(doorways[i], cell, goal, distances);
            List<Integer> mine = batch.get(i);
            if (open[i] >= 0) {
                mine.retainAll(queues.get(open[i]));
            }
            if (mine.isEmpty() || --roundsLeft[i] <= 0) {
                turn(i, queues, cell);
            }
            for (int r : batch.get(i)) {
                rank[r] = IN_BATCH;
            }
        }
        return rank;
    }

    /** @return whether the doorway's batch comes from this side now (for tests and logs) */
    int side(int doorway) {
        return open[doorway];
    }

    /** @return how many doorways the map has */
    int doorways() {
        return doorways.length;
    }

    /** The batch ended: the door turns to the other side if robots wait there, else stays with this side's queue. */
    private void turn(int i, List<List<Integer>> queues, int[] cell) {
        int from = open[i];
        int next;
        if (from >= 0 && !queues.get(1 - from).isEmpty()) {
            next = 1 - from;
        } else if (from >= 0 && !queues.get(from).isEmpty()) {
            next = from;
        } else {
            next = queues.get(1).size() > queues.get(0).size() ? 1 : queues.get(0).isEmpty() ? -1 : 0;
        }
        List<Integer> mine = batch.get(i);
        mine.clear();
        open[i] = next;
        if (next < 0) {
            return;
        }
        int exit = map.passageExit(doorways[i], next);
        List<Integer> queue = new ArrayList<>(queues.get(next));
        queue.sort(Comparator.comparingInt((Integer r) -> map.manhattan(cell[r], exit)).thenComparingInt(r -> r));
        mine.addAll(queue.subList(0, Math.min(MAX_BATCH, queue.size())));
        roundsLeft[i] = ROUNDS_PER_ROBOT * mine.size() + SLACK_ROUNDS;
    }

    /** @return the robots queued on side 0 and side 1 of the doorway */
    private List<List<Integer>> queues(int doorway, int[] cell, int[] goal, Distances distances) {
        List<List<Integer>> queues = List.of(new ArrayList<>(), new ArrayList<>());
        int[] exit = { map.passageExit(doorway, 0), map.passageExit(doorway, 1) };
        for (int r = 0; r < cell.length; r++) {
            int c = cell[r];
            if (c < 0 || goal[r] == FleetPlanner.NO_GOAL || map.passage(c) == doorway) {
                continue;
            }
            int near0 = map.manhattan(c, exit[0]);
            int near1 = map.manhattan(c, exit[1]);
            int side = near0 <= near1 ? 0 : 1;
            int here = Math.min(near0, near1);
            if (here > QUEUE_STEPS) {
                continue;
            }
            int[] d = distances.to(goal[r]);
            boolean beyond = d[exit[1 - side]] < d[exit[side]];
            boolean onTheWay = d[c] < Distances.UNREACHABLE && d[c] >= here + d[exit[side]];
            if (beyond && onTheWay) {
                queues.get(side).add(r);
            }
        }
        return queues;
    }
}
