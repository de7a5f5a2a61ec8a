package eu.brain.iot.behaviours.warehouse.traffic;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Deque;
import java.util.function.IntPredicate;

/**
 * The fleet's space-time plan, made again every step over a rolling window (windowed cooperative A*): robots are
 * planned one after the other, each through the reservations of those before it, and every robot not planned yet
 * holds only the cell it stands in now, so a robot planned earlier may plan to drive through it: the later robot
 * then plans to make way (a push, as in PIBT). A robot that finds no path clear of the others (boxed in, or offline)
 * stays where it is for the whole window, and every robot whose path met it is planned again around it; standing
 * still never meets anyone, so every round ends with a plan in which no two robots' stays in a cell overlap or
 * follow each other without a free step between (robot-sim's rule).
 * <p>
 * <b>Who goes first</b>: robots driving along a leg sent earlier ({@link #committed}), robots inside a passage (they
 * drive on through it, one way), the robots of a door's batch ({@link DoorBatches}: a doorway crossed one direction
 * at a time), then the robot that has gone longest without coming closer to its goal, then robots carrying a cart,
 * then the caller's bias ({@link #bias}), then the lower index. A robot that makes no progress thus rises until it
 * is first (at a door, first of its batch, which comes within a bounded number of rounds), and the first robot gets
 * its best path through everyone else's current cells: that is why no robot waits for ever on a map
 * {@link MapCheck} accepts (behaviours/README.md, "Traffic").
 * <p>
 * Robots are numbered 0..n-1 by the caller. Not thread-safe: one thread (the behaviour's binding thread) owns a
 * planner and everything it returns.
 */
public final class FleetPlanner {
    /** The robot has no goal: it stays where it is unless pushed. */
    public static final int NO_GOAL = -1;

    private final TrafficMap map;
    private final int window;
    private final ReservationTable table;
    private final SpaceTimeSearch search;
    private final Distances distances;
    private final int[] cell;
    private final int[][] committed;
    private final int[] goal;
    private final boolean[] carrying;
    private final boolean[] offline;
    private final int[] bias;
    /** The door policy: a doorway crossed in batches, one direction at a time. */
    private final DoorBatches doors;
    private final int[] stuck;
    private final int[] lastDistance;
    private final int[] lastGoal;
    private final int[][] path;
    private final boolean[] stationary;
    /** Each robot's direction in the passage it stands in (+1 towards end B, -1 towards A, 0 not in one). */
    private final int[] heading;
    /** Who drives through which passage when, this round. */
    private final PassageClaims claims = new PassageClaims();
    private final boolean[] planned;
    /** Whether a robot waits in the queue of robots to plan again (held robots took their cells). */
    private final boolean[] queued;
    /** The robot standing in each cell now, -1 for none. */
    private final int[] occupant;
    /** The cells {@link #occupant} was filled for in the last round. */
    private final int[] occupiedBefore;
    private static final int MAX_PUSH_DEPTH = 6;
    /** Goals' distance tables kept beyond one per robot (goals just left, robots standing in passages). */
    private static final int DISTANCE_TABLES_SPARE = 64;
    /** Search nodes a robot may expand per step of the window (bounds the time of a search that finds no way). */
    private static final int SEARCH_BUDGET_PER_STEP = 200;
    private static final int MAX_PUSH_RETRIES = 6;
    private boolean[] carts;
    /** The robot being searched for now (its own cell is never in its way). */
    private int searching;
    /** A cell where a robot not planned yet stands: at the deepest push, it cannot make way any more. */
    private final IntPredicate unpushable = this::unpushable;
    private final Integer[] order;
    private long rounds;
    private long fallbacks;

    /**
     * @param robots how many robots (numbered 0..robots-1)
     * @param window steps planned ahead (at least 2; longer than the longest lane of the map, see {@link MapCheck})
     */
    public FleetPlanner(TrafficMap map, int robots, int window) {
        if (window < 2) {
            throw new IllegalArgumentException("the planning window must be at least 2 steps, was " + window);
        }
        this.map = map;
        this.window = window;
        this.table = new ReservationTable(map.cells(), window);
        this.search = new SpaceTimeSearch(map, table, SEARCH_BUDGET_PER_STEP * (window + 1));
        this.distances = new Distances(map, robots + DISTANCE_TABLES_SPARE);
        cell = new int[robots];
        committed = new int[robots][];
        Arrays.fill(committed, new int[0]);
        goal = new int[robots];
        carrying = new boolean[robots];
        offline = new boolean[robots];
        bias = new int[robots];
        doors = new DoorBatches(map, robots);
        stuck = new int[robots];
        lastDistance = new int[robots];
        lastGoal = new int[robots];
        path = new int[robots][window + 1];
        stationary = new boolean[robots];
        heading = new int[robots];
        search.claims(claims);
        planned = new boolean[robots];
        queued = new boolean[robots];
        occupant = new int[map.cells()];
        occupiedBefore = new int[robots];
        Arrays.fill(occupiedBefore, -1);
        Arrays.fill(occupant, -1);
        order = new Integer[robots];
        Arrays.fill(goal, NO_GOAL);
        Arrays.fill(lastGoal, NO_GOAL);
        Arrays.fill(cell, -1);
        carts = new boolean[map.cells()];
    }

    public TrafficMap map() {
        return map;
    }

    public int window() {
        return window;
    }

    public int robots() {
        return cell.length;
    }

    /**
     * Where a robot stands now and where it goes.
     *
     * @param at       its cell (a robot never placed is left out of the plan)
     * @param to       its goal cell, or {@link #NO_GOAL}
     * @param loaded   whether it carries a cart (it then cannot drive under another)
     * @param isOffline whether it is offline: an obstacle that holds its cell until it is seen again
     */
    public void robot(int robot, int at, int to, boolean loaded, boolean isOffline) {
        cell[robot] = at;
        goal[robot] = to;
        carrying[robot] = loaded;
        offline[robot] = isOffline;
    }

    /**
     * The leg the robot drives along now (sent earlier): its cells at steps 1, 2, ... of this round, or an empty
     * array. Robots on a leg are planned first, the leg kept.
     */
    public void committed(int robot, int[] cells) {
        committed[robot] = cells;
    }

    /** The cells with a cart on the floor (a robot carrying a cart cannot drive under them). */
    public void carts(boolean[] cartCells) {
        this.carts = cartCells;
    }

    /** A rank the caller adds to the robot's priority: higher goes first among equally stuck robots. */
    public void bias(int robot, int rank) {
        bias[robot] = rank;
    }

    /** Steps the robot has gone without coming closer to its goal (its priority). */
    public int stuck(int robot) {
        return stuck[robot];
    }

    /** Rounds planned so far. */
    public long rounds() {
        return rounds;
    }

    /** Robots held still because they found no path clear of the others, over all rounds. */
    public long fallbacks() {
        return fallbacks;
    }

    /** Search nodes expanded over all rounds. */
    public long expansions() {
        return search.expansions();
    }

    /** @return the robot's planned cell at each step 0..window of the last round (do not modify) */
    public int[] path(int robot) {
        return path[robot];
    }

    /** @return whether the robot was held still in the last round (no path clear of the others) */
    public boolean held(int robot) {
        return stationary[robot];
    }

    /** Plans one round from the robots' cells now. */
    public void plan() {
        rounds++;
        table.clear();
        for (int c : occupiedBefore) {
            if (c >= 0) {
                occupant[c] = -1;
            }
        }
        claims.clear();
        for (int r = 0; r < cell.length; r++) {
            heading(r, occupiedBefore[r]);
        }
        System.arraycopy(cell, 0, occupiedBefore, 0, cell.length);
        int n = cell.length;
        for (int r = 0; r < n; r++) {
            stationary[r] = false;
            planned[r] = false;
            queued[r] = false;
            if (cell[r] < 0) {
                continue;
            }
            occupant[cell[r]] = r;
            progress(r);
            table.reserve(r, cell[r], 0);
            if (offline[r]) {
                hold(r);
            }
        }
        int[] batch = doors.ranks(cell, goal, distances);
        int count = 0;
        for (int r = 0; r < n; r++) {
            if (cell[r] >= 0 && !offline[r]) {
                order[count++] = r;
            }
        }
        Arrays.sort(order, 0, count, (a, b) -> {
            if ((committed[a].length > 0) != (committed[b].length > 0)) {
                return committed[a].length > 0 ? -1 : 1; // robots driving along a leg first: they cannot stop
            }
            if ((heading[a] != 0) != (heading[b] != 0)) {
                return heading[a] != 0 ? -1 : 1; // robots in a passage first: they drive on through it
            }
            if (batch[a] != batch[b]) {
                return Integer.compare(batch[b], batch[a]); // a door's batch: one direction at a time
            }
            if (stuck[a] != stuck[b]) {
                return Integer.compare(stuck[b], stuck[a]);
            }
            if (carrying[a] != carrying[b]) {
                return carrying[a] ? -1 : 1;
            }
            if (bias[a] != bias[b]) {
                return Integer.compare(bias[b], bias[a]);
            }
            return Integer.compare(a, b);
        });
        Deque<Integer> again = new ArrayDeque<>();
        int budget = 4 * n + 16;
        for (int i = 0; i < count; i++) {
            if (!planned[order[i]] && !planOne(order[i], 0)) {
                fallbacks++;
                hold(order[i], again);
            }
            while (!again.isEmpty()) {
                int r = again.poll();
                queued[r] = false;
                if (budget-- > 0 && planOne(r, 0)) {
                    continue;
                }
                if (!stationary[r]) {
                    fallbacks++;
                    hold(r, again); // the budget spent: standing still is always clear (see hold)
                }
            }
        }
    }

    /**
     * The direction of a robot in a passage: the way it entered (from its cell in the last round), kept while it is
     * in; a robot first seen inside heads for the end nearer its goal. The passage is one-way that way this round.
     */
    private void heading(int r, int before) {
        int run = cell[r] < 0 ? -1 : map.passage(cell[r]);
        if (run < 0) {
            heading[r] = 0;
            return;
        }
        if (before >= 0 && before != cell[r]) {
            // entered from outside, or moved along it: pushed back against the way it came in, it now drives the
            // way it moves, as do the robots that pushed it (else two claims of one passage would face each other)
            heading[r] = SpaceTimeSearch.moveDirection(map, before, cell[r], run);
        } else if (heading[r] == 0 || before < 0) { // first seen in it, or standing where it stood
            int g = goal[r] == NO_GOAL ? cell[r] : goal[r];
            int[] d = distances.to(g);
            heading[r] = d[map.passageExit(run, 1)] <= d[map.passageExit(run, 0)] ? 1 : -1;
        }
        claims.add(r, run, heading[r], 0, window); // until its plan says when it leaves
    }

    /**
     * Where the robot plans for this round: its goal; but a robot in a passage heading away from its goal (it made way
     * for robots coming the other way) plans for the passage's end ahead of it, so that it drives on out of the
     * passage instead of stopping in it, facing the way it came, in front of the robots that follow it.
     */
    private int wayOn(int r) {
        int run = map.passage(cell[r]);
        if (run < 0 || heading[r] == 0) {
            return goal[r];
        }
        int ahead = map.passageExit(run, heading[r] > 0 ? 1 : 0);
        int behind = map.passageExit(run, heading[r] > 0 ? 0 : 1);
        int[] d = distances.to(goal[r]);
        return d[ahead] > d[behind] ? ahead : goal[r];
    }

    private void progress(int r) {
        int d = goal[r] == NO_GOAL ? 0 : distances.to(goal[r])[cell[r]];
        if (goal[r] != lastGoal[r] || d == 0 || d < lastDistance[r]) {
            stuck[r] = 0;
            lastDistance[r] = d;
            lastGoal[r] = goal[r];
        } else {
            stuck[r]++;
        }
    }

    /**
     * Plans one robot; every robot not planned yet whose cell its path drives through is planned at once after it
     * (it inherits the priority, as in PIBT), and when such a robot cannot make way, this robot is planned again
     * with that robot's cell kept clear. At the deepest push ({@link #MAX_PUSH_DEPTH}) nobody can be pushed any
     * more: when the robot's best path meets a robot not planned yet, its second search keeps clear of all of them.
     *
     * @return whether the robot has a plan (else it has no reservation beyond step 0)
     */
    private boolean planOne(int r, int depth) {
        int to = goal[r] == NO_GOAL ? cell[r] : wayOn(r);
        boolean[] blocked = carrying[r] ? carts : null;
        int[] forbidden = new int[0];
        int[] until = new int[0];
        for (int attempt = 0; attempt <= MAX_PUSH_RETRIES; attempt++) {
            if (planned[r]) {
                return true; // planned meanwhile, pushed by the robot that went first
            }
            search.depth(depth);
            // at the deepest push nobody in the way can be pushed: once the best path met one, the next search
            // keeps clear of all of them at once rather than learn them one retry at a time
            searching = r;
            search.immovable(depth >= MAX_PUSH_DEPTH && attempt > 0 ? unpushable : null);
            int[] found = search.find(r, cell[r], to, to == cell[r] ? distances.around(to, window) : distances.to(to),
                    blocked, forbidden, until, heading[r], committed[r]);
            // no way to the goal through the others: at least make way, unless the search found no way to the
            // window's end at all (every step it could take was tried): the way out would meet the same walls
            boolean boxedIn = search.exhausted() && (blocked == null || !blocked[cell[r]]);
            if (found == null && to != cell[r] && !boxedIn) {
                found = search.find(r, cell[r], cell[r], distances.around(cell[r], window), blocked, forbidden,
                        until, heading[r], committed[r]);
            }
            if (found == null) {
                return false;
            }
            System.arraycopy(found, 0, path[r], 0, window + 1);
            for (int t = 1; t <= window; t++) {
                table.reserve(r, found[t], t);
            }
            planned[r] = true;
            claims.remove(r);
            claims.claim(map, r, found, heading[r]);
            int refused = pushThrough(r, depth);
            if (refused < 0) {
                return true;
            }
            release(r);
            planned[r] = false;
            if (attempt == 0 && depth < MAX_PUSH_DEPTH && planOne(refused, depth + 1)) {
                continue; // the robot that could not make way goes first, and may push this one
            }
            // give the robot in the way one more step to go each time (a chain of robots backing out of a lane
            // needs a step per robot: robot-sim lets no one into a cell left in the same step)
            int known = indexOf(forbidden, cell[refused]);
            if (known < 0) {
                forbidden = Arrays.copyOf(forbidden, forbidden.length + 1);
                until = Arrays.copyOf(until, until.length + 1);
                known = forbidden.length - 1;
                forbidden[known] = cell[refused];
                until[known] = 2;
            } else {
                until[known] = attempt + 2 >= MAX_PUSH_RETRIES ? window : until[known] + 1;
            }
        }
        return false;
    }

    private boolean unpushable(int c) {
        int o = occupant[c];
        return o >= 0 && o != searching && !planned[o];
    }

    private static int indexOf(int[] cells, int c) {
        for (int i = 0; i < cells.length; i++) {
            if (cells[i] == c) {
                return i;
            }
        }
        return -1;
    }

    /** @return the first robot in the way of r's path that could not make way, or -1 when all could */
    private int pushThrough(int r, int depth) {
        int[] p = path[r];
        for (int t = 1; t <= window; t++) {
            int o = occupant[p[t]];
            if (o < 0 || o == r || planned[o] || offline[o] || stationary[o]) {
                continue;
            }
            if (depth >= MAX_PUSH_DEPTH || !planOne(o, depth + 1)) {
                return o;
            }
        }
        return -1;
    }

    /** An offline robot stands still for the whole window (held before anyone is planned). */
    private void hold(int r) {
        hold(r, new ArrayDeque<>());
    }

    /**
     * The robot stands still for the whole window: every robot already planned through its cell (or into it right
     * after, or out of it right before) loses its plan and is planned again around it.
     */
    private void hold(int r, Deque<Integer> again) {
        stationary[r] = true;
        planned[r] = true;
        int c = cell[r];
        for (int t = 1; t <= window; t++) {
            for (int s = t - 1; s <= Math.min(window, t + 1); s++) {
                int o = table.owner(c, s);
                // step 0 is where robots stand now: two robots seen in one cell (a stale position) release nothing
                if (o != ReservationTable.NONE && o != r && s >= 1) {
                    release(o);
                    planned[o] = false;
                    if (!queued[o]) {
                        queued[o] = true;
                        again.add(o);
                    }
                }
            }
            table.reserve(r, c, t);
        }
        Arrays.fill(path[r], c);
    }

    private void release(int o) {
        for (int t = 1; t <= window; t++) {
            table.release(o, path[o][t], t);
        }
        claims.remove(o);
        if (heading[o] != 0) {
            claims.add(o, map.passage(cell[o]), heading[o], 0, window);
        }
    }
}
