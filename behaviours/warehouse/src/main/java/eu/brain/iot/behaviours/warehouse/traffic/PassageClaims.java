package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.Arrays;

/**
 * Who drives through which passage (a one-cell lane joining two open cells, or a doorway) in which direction and
 * when, over the planning window: each robot's plan claims the steps from its entry into a passage to its exit (to
 * the window's end when it does not leave it within the window; from step 0 when it stands in one). Two claims of
 * opposite directions on one passage never overlap in time, so a passage only ever holds robots going one way and no
 * robot meets another head-on in it, within the window or after it (robots standing in a passage drive on the way
 * they came in). Cleared every round. Owned by the planner's thread.
 */
final class PassageClaims {
    private int[] robot = new int[64];
    private int[] passage = new int[64];
    private int[] direction = new int[64];
    private int[] from = new int[64];
    private int[] to = new int[64];
    private int size;

    void clear() {
        size = 0;
    }

    void add(int r, int run, int dir, int first, int last) {
        if (size == robot.length) {
            int n = size * 2;
            robot = Arrays.copyOf(robot, n);
            passage = Arrays.copyOf(passage, n);
            direction = Arrays.copyOf(direction, n);
            from = Arrays.copyOf(from, n);
            to = Arrays.copyOf(to, n);
        }
        robot[size] = r;
        passage[size] = run;
        direction[size] = dir;
        from[size] = first;
        to[size] = last;
        size++;
    }

    /** Forgets the robot's claims. */
    void remove(int r) {
        int kept = 0;
        for (int i = 0; i < size; i++) {
            if (robot[i] != r) {
                robot[kept] = robot[i];
                passage[kept] = passage[i];
                direction[kept] = direction[i];
                from[kept] = from[i];
                to[kept] = to[i];
                kept++;
            }
        }
        size = kept;
    }

    /** @return whether a robot other than r claims the passage at step t in a direction other than dir */
    boolean against(int r, int run, int dir, int t) {
        for (int i = 0; i < size; i++) {
            if (passage[i] == run && robot[i] != r && direction[i] != dir && from[i] <= t && t <= to[i]) {
                return true;
            }
        }
        return false;
    }

    /** @return whether a robot other than r claims the passage at step t in the given direction */
    boolean along(int r, int run, int dir, int t) {
        for (int i = 0; i < size; i++) {
            if (passage[i] == run && robot[i] != r && direction[i] == dir && from[i] <= t && t <= to[i]) {
                return true;
            }
        }
        return false;
    }

    /** Claims the passages a planned path drives through. */
    void claim(TrafficMap map, int r, int[] path, int startHeading) {
        int window = path.length - 1;
        int run = map.passage(path[0]);
        int dir = run >= 0 ? startHeading : 0;
        int entered = 0;
        for (int t = 1; t <= window; t++) {
            int now = map.passage(path[t]);
            if (now != run) {
                if (run >= 0) {
                    add(r, run, dir, entered, t - 1);
                }
                run = now;
                entered = t;
                dir = run >= 0 ? SpaceTimeSearch.moveDirection(map, path[t - 1], path[t], run) : 0;
            } else if (run >= 0 && path[t] != path[t - 1]) {
                dir = SpaceTimeSearch.moveDirection(map, path[t - 1], path[t], run);
            }
        }
        if (run >= 0) {
            add(r, run, dir == 0 ? 1 : dir, entered, window);
        }
    }
}
