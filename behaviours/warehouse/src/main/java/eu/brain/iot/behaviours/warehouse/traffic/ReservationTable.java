package eu.brain.iot.behaviours.warehouse.traffic;

/**
 * Who stands where over the planning window: one owner per (cell, step), steps 0 (now) to the window's end. It
 * encodes robot-sim's movement rule: a robot enters only a cell that was empty at the start of the step, so two
 * robots' stays in one cell are at least one step apart; {@link #free} therefore looks at the step before and after
 * too. Cleared for every planning round (a round number, no array is wiped). Owned by the planner's thread.
 */
final class ReservationTable {
    static final int NONE = -1;

    private final int window;
    /** Steps per cell: the entries of one cell lie side by side, so {@link #free} reads one stretch of memory. */
    private final int steps;
    /** Per (cell, step): the round in the high 32 bits, the owner in the low 32 (an older round: nobody). */
    private final long[] entry;
    private int round = 1;

    ReservationTable(int cells, int window) {
        this.window = window;
        this.steps = window + 1;
        this.entry = new long[cells * steps];
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
        long e = entry[cell * steps + t];
        return (int) (e >>> 32) == round ? (int) e : NONE;
    }

    void reserve(int robot, int cell, int t) {
        entry[cell * steps + t] = (long) round << 32 | (robot & 0xffffffffL);
    }

    /** Takes back the robot's reservation of the cell at step t, if it holds it. */
    void release(int robot, int cell, int t) {
        int i = cell * steps + t;
        if (owner(cell, t) == robot) {
            entry[i] = 0;
        }
    }

    /**
     * @return whether the robot may stand in the cell at step t: no other robot stands there at t, nor at t - 1
     *         (it could not have been entered) nor at t + 1 (the other could not enter it)
     */
    boolean free(int robot, int cell, int t) {
        return blocker(robot, cell, t) == NONE;
    }

    /** @return a robot other than {@code robot} whose reservation {@link #free} would meet, or {@link #NONE} */
    int blocker(int robot, int cell, int t) {
        int base = cell * steps;
        for (int s = Math.max(0, t - 1); s <= Math.min(window, t + 1); s++) {
            long e = entry[base + s];
            if ((int) (e >>> 32) == round && (int) e != robot) {
                return (int) e;
            }
        }
        return NONE;
    }
}
