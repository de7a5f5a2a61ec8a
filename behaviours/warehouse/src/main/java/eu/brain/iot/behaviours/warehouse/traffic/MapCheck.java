package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The maps on which {@link FleetPlanner} guarantees progress, and why a map is refused. The planner needs:
 * <ul>
 * <li>every passable cell reachable from every other (else some goal is never reached);</li>
 * <li>every doorway joining two cells on opposite sides (a door in a dead end or beside another door is a passage
 * the planner cannot see through);</li>
 * <li>every run of lane cells (one-cell passages, dead ends) shorter than the planning window: a robot enters a lane
 * only when its reserved path leaves it within the window (or ends at its goal there), so a longer lane could never
 * be crossed, and robots in it could meet head-on.</li>
 * </ul>
 * Stateless.
 */
public final class MapCheck {
    private MapCheck() {
    }

    /** @return why the planner cannot guarantee progress on this map with this window, or empty when it can */
    public static Optional<String> refusal(TrafficMap map, int window) {
        List<String> why = new ArrayList<>();
        connected(map).ifPresent(why::add);
        doors(map).ifPresent(why::add);
        lanes(map, window).ifPresent(why::add);
        return why.isEmpty() ? Optional.empty() : Optional.of(String.join("; ", why));
    }

    private static Optional<String> connected(TrafficMap map) {
        int start = -1;
        int passable = 0;
        for (int c = 0; c < map.cells(); c++) {
            if (map.passable(c)) {
                passable++;
                start = start < 0 ? c : start;
            }
        }
        if (start < 0) {
            return Optional.of("the map has no passable cell");
        }
        boolean[] seen = new boolean[map.cells()];
        int reached = flood(map, start, seen, c -> true);
        if (reached == passable) {
            return Optional.empty();
        }
        for (int c = 0; c < map.cells(); c++) {
            if (map.passable(c) && !seen[c]) {
                return Optional.of((passable - reached) + " passable cells, " + map.cell(c) + " the first, cannot be "
                        + "reached from " + map.cell(start) + ": join them or wall them off");
            }
        }
        return Optional.empty();
    }

    private static Optional<String> doors(TrafficMap map) {
        for (int c = 0; c < map.cells(); c++) {
            if (!map.door(c)) {
                continue;
            }
            int x = c % map.width();
            int y = c / map.width();
            boolean across = open(map, x, y - 1) && open(map, x, y + 1);
            boolean along = open(map, x - 1, y) && open(map, x + 1, y);
            if (map.neighbours(c).length != 2 || !(across || along)) {
                return Optional.of("the door at " + map.cell(c) + " does not join two cells on opposite sides "
                        + "(a door in a dead end, in a corner or beside another door): put it in a straight wall");
            }
        }
        return Optional.empty();
    }

    private static boolean open(TrafficMap map, int x, int y) {
        return x >= 0 && y >= 0 && x < map.width() && y < map.height() && map.passable(map.cell(x, y))
                && !map.door(map.cell(x, y));
    }

    private static Optional<String> lanes(TrafficMap map, int window) {
        boolean[] seen = new boolean[map.cells()];
        for (int c = 0; c < map.cells(); c++) {
            if (map.lane(c) && !seen[c]) {
                int length = flood(map, c, seen, map::lane);
                if (length >= window) {
                    return Optional.of("a one-cell passage of " + length + " cells from " + map.cell(c)
                            + " is not shorter than the planning window (" + window + " steps): robots in it could "
                            + "meet head-on; widen it to two cells, add passing places, or plan further ahead");
                }
            }
        }
        return Optional.empty();
    }

    private static int flood(TrafficMap map, int start, boolean[] seen, java.util.function.IntPredicate within) {
        int[] queue = new int[map.cells()];
        int head = 0;
        int tail = 0;
        queue[tail++] = start;
        seen[start] = true;
        while (head < tail) {
            int c = queue[head++];
            for (int n : map.neighbours(c)) {
                if (!seen[n] && within.test(n)) {
                    seen[n] = true;
                    queue[tail++] = n;
                }
            }
        }
        return tail;
    }
}
