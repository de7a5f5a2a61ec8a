package eu.brain.iot.behaviours.warehouse.traffic;

/**
 * Who stands where over the planning window: one owner per (cell, step), steps 0 (now) to the window's end. It
 * encodes robot-sim's movement rule: a robot enters only a cell that was empty at the start of the step, so two
 * robots' stays in one cell are at least one step apart; {@link #free} therefore looks at the step before and after
 * too. Cleared for every planning round (a stamp, no array is wiped). Owned by the planner's thread.
 */
final class ReservationTable {
    static final int NONE = -1;

    private final int cells;
    private final int window;
    private final int[] owner;
    private final int[] stamp;
    private int round = 1;

    ReservationTable(int cells, int window) {
        this.cells = cells;
        this.window = window;
        this.owner = new int[cells * (window + 1)];
        this.stamp = new int[owner.length];
    }

    int window() {
        return window;
    }

    /** Forgets every reservation. */
    void clear() {
        round++;
    }

    /** @return the robot that stands in the cell at step t (0..window), or {@link #NONE} */
    int owner(int cell, int t) {
        int i = t * cells + cell;
        return stamp[i] == round ? owner[i] : NONE;
    }

    void reserve(int robot, int cell, int t) {
        int i = t * cells + cell;
        owner[i] = robot;
        stamp[i] = round;
    }

    /** Takes back the robot's reservation of the cell at step t, if it holds it. */
    void release(int robot, int cell, int t) {
        int i = t * cells + cell;
        if (stamp[i] == round && owner[i] == robot) {
            stamp[i] = 0;
        }
    }

    /**
     * @return whether the robot may stand in the cell at step t: no other robot stands there at t, nor at t - 1
     *         (it could not have been entered) nor at t + 1 (the other could not enter it)
     */
    boolean free(int robot, int cell, int t) {
        for (int s = Math.max(0, t - 1); s <= Math.min(window, t + 1); s++) {
            int o = owner(cell, s);
            if (o != NONE && o != robot) {
                return false;
            }
        }
        return true;
    }

    /** @return a robot other than {@code robot} whose reservation {@link #free} would meet, or {@link #NONE} */
    int blocker(int robot, int cell, int t) {
        for (int s = Math.max(0, t - 1); s <= Math.min(window, t + 1); s++) {
            int o = owner(cell, s);
            if (o != NONE && o != robot) {
                return o;
            }
        }
        return NONE;
    }
}
