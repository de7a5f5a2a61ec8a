package eu.brain.iot.behaviours.robot.impl;

import java.util.Optional;

import eu.brain.iot.behaviours.warehouse.Cell;

/**
 * What a transition of a robot's model asks of the fleet: an extern function's effect ({@link RobotExterns}), made on
 * the node that hosts the robot's model instance and carried to the instance that drives the fleet in a
 * {@link RobotModelReport} ({@link #text} and {@link #parse}: {@code MOVE_ON}, {@code STEP_ASIDE 4 2}, {@code LIFT},
 * {@code PLACE}).
 *
 * @param kind what the fleet does for the robot
 * @param aside the cell to step aside to ({@link Kind#STEP_ASIDE}), else {@code null}
 */
record ModelStep(Kind kind, Cell aside) {

    /** The extern functions' effects on the fleet. */
    enum Kind {
        /** {@code moveTo} with an area code: the robot goes on with its errand. */
        MOVE_ON,
        /** {@code moveTo} with a cell the orchestrator chose: the robot steps aside to it. */
        STEP_ASIDE,
        /** {@code liftCart}: the robot lifts the cart it stands under, then heads for storage. */
        LIFT,
        /** {@code placeCart}: the robot puts its cart down in storage, then heads for its dock. */
        PLACE
    }

    static final ModelStep MOVE_ON = new ModelStep(Kind.MOVE_ON, null);
    static final ModelStep LIFT = new ModelStep(Kind.LIFT, null);
    static final ModelStep PLACE = new ModelStep(Kind.PLACE, null);

    static ModelStep aside(Cell cell) {
        return new ModelStep(Kind.STEP_ASIDE, cell);
    }

    /** @return the step as a report carries it */
    String text() {
        return aside == null ? kind.name() : kind.name() + " " + aside.x() + " " + aside.y();
    }

    /** @return the step a report's text names, or empty for text that is not one (logged by the caller) */
    static Optional<ModelStep> parse(String text) {
        if (text == null) {
            return Optional.empty();
        }
        String[] words = text.trim().split(" ");
        try {
            Kind kind = Kind.valueOf(words[0]);
            if (kind == Kind.STEP_ASIDE) {
                return words.length == 3
                        ? Optional.of(aside(new Cell(Integer.parseInt(words[1]), Integer.parseInt(words[2]))))
                        : Optional.empty();
            }
            return words.length == 1 ? Optional.of(new ModelStep(kind, null)) : Optional.empty();
        } catch (IllegalArgumentException e) { // an unknown kind, or a coordinate that is not a whole number
            return Optional.empty();
        }
    }
}
