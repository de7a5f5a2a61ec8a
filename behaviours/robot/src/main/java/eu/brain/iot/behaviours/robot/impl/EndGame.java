package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * At the end of the warehouse's work, which of the carts left a robot at its dock takes, and which it leaves to a
 * robot that will be back and done with them sooner.
 * <p>
 * While there are more unclaimed carts than other robots, every robot takes one: a robot left waiting is time lost.
 * Once there are as many or fewer, each cart left is the last errand of some robot, and the warehouse ends with the
 * latest of them: a robot whose dock is far from the door a cart lies behind would cross the warehouse twice for it,
 * while a robot docked near that door, back a little later, is done with it sooner (BENCHMARKS.md, "With the traffic
 * planner", has the figures).
 * So a robot leaves a cart to another robot whose estimated finish is earlier by more than {@link #MARGIN_STEPS}:
 * <ul>
 * <li>a robot's finish with a cart: the steps until it is back at its dock (0 for this robot) plus twice the steps
 * from its dock to the cart by path, out and back (storage lies between the docks and the doors); the way through
 * the door the cart lies behind ({@link DoorShares#stepsFromDoorOf}) is the same for every robot, so only the steps
 * from that door to each dock are compared;</li>
 * <li>the steps until a robot out is back: by the cells on its way (going for a cart: to it and from it home;
 * carrying one: to its storage cell and home; going home: home), counted as the crow flies.</li>
 * </ul>
 * A robot that leaves every cart to others claims nothing now and looks again at its next turn.
 * <p>
 * Stateless: any thread.
 */
final class EndGame {

    /** How much sooner another robot must be done with a cart for this one to leave it (steps: 5 s). */
    static final int MARGIN_STEPS = 10;

    private EndGame() {
    }

    /**
     * Another robot, as far as the end of the work goes.
     *
     * @param dock          its dock
     * @param stepsUntilBack the steps until it is back at its dock, ready for a cart (0: it is there)
     */
    record Other(Cell dock, int stepsUntilBack) {
    }

    /**
     * @param dock       the dock of the robot about to claim, where it stands
     * @param candidates the carts it may claim
     * @param others     every other robot of the fleet that may take another cart
     * @return the candidates it takes rather than leave to another robot: all of them while there are more
     *         candidates than other robots
     */
    static List<CartState> worthTaking(Cell dock, List<CartState> candidates, List<Other> others, DoorShares shares,
            Grid grid) {
        if (candidates.size() > others.size() || others.isEmpty()) {
            return candidates;
        }
        List<CartState> taken = new ArrayList<>(candidates.size());
        for (CartState c : candidates) {
            Map<Cell, Integer> fromDoor = shares.stepsFromDoorOf(c.cell(), grid);
            Integer mine = fromDoor.get(dock);
            if (mine == null || others.stream().noneMatch(o -> sooner(o, fromDoor, mine))) {
                taken.add(c);
            }
        }
        return taken;
    }

    private static boolean sooner(Other o, Map<Cell, Integer> fromDoor, int mine) {
        Integer theirs = fromDoor.get(o.dock());
        return theirs != null && o.stepsUntilBack() + 2 * theirs + MARGIN_STEPS < 2 * mine;
    }

    /**
     * The steps until a robot is back at its dock, as the crow flies along its way.
     *
     * @param at   where it stands
     * @param via  where its errand takes it before home (its cart, or its storage cell), or {@code null}: home
     * @param dock its dock
     */
    static int stepsUntilBack(Cell at, Cell via, Cell dock) {
        return via == null ? at.distance(dock) : at.distance(via) + via.distance(dock);
    }
}
