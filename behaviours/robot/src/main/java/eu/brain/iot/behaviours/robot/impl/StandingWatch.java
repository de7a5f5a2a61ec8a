package eu.brain.iot.behaviours.robot.impl;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import eu.brain.iot.behaviours.warehouse.Cell;

/**
 * Tells, once per stand, of a robot that has stood on one cell with an errand for {@link #LOOKS} looks at it (a look
 * per poll, a minute of warehouse time, or less with the events about it in between): where, its errand, and its
 * model's places, so that a robot left behind by the rules shows in the node's log with what it waits for. A robot
 * that moves, or whose errand or places change, starts a new stand.
 * <p>
 * Not thread-safe: owned by the binding's thread.
 */
final class StandingWatch {

    /** Looks on one cell with the same errand and places before the robot is reported (120 looks: 60 s). */
    static final int LOOKS = 120;

    private record Stand(Cell cell, Errands.Errand errand, List<String> places, int looks) {
    }

    private final Map<String, Stand> stands = new HashMap<>();

    /**
     * @return the line to log when the robot has just stood {@link #LOOKS} looks with an errand; empty otherwise
     */
    Optional<String> look(String robot, Cell cell, Errands.Errand errand, List<String> places) {
        if (errand.leg() == Errands.Leg.NONE) {
            stands.remove(robot);
            return Optional.empty();
        }
        Stand s = stands.get(robot);
        Stand next = s != null && s.cell().equals(cell) && s.errand().equals(errand) && s.places().equals(places)
                ? new Stand(cell, errand, places, s.looks() + 1) : new Stand(cell, errand, List.copyOf(places), 1);
        stands.put(robot, next);
        if (next.looks() != LOOKS) {
            return Optional.empty();
        }
        return Optional.of(robot + " has stood at " + cell + " for " + LOOKS + " looks on its errand (" + errand.leg()
                + ", cart " + errand.cart() + ", storage cell " + errand.drop() + ", dock " + errand.dock()
                + "), its model in " + places);
    }
}
