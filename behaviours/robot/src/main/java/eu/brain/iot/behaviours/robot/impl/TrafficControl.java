package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BiConsumer;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotNames;
import eu.brain.iot.behaviours.warehouse.RobotState;
import eu.brain.iot.behaviours.warehouse.traffic.FleetPlanner;
import eu.brain.iot.behaviours.warehouse.traffic.MapCheck;
import eu.brain.iot.behaviours.warehouse.traffic.TrafficMap;
import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.GoToCommand;

/**
 * Drives the robots along the fleet's reserved paths: the errands say where each robot goes ({@link #goal}), the
 * {@link FleetPlanner} plans every robot over a rolling window at every look, and each robot standing still is sent
 * on a <em>leg</em>: a go-to to the end of the straight run of cells its plan moves it through without waiting
 * (robot-sim's own path to a cell in a straight line is that line, so robot-sim's planner never decides who meets
 * whom). A robot driving along a leg keeps it (the planner plans around it); a robot whose plan says wait gets no
 * go-to. An offline robot is an obstacle that holds its cell until it is seen again.
 * <p>
 * A robot stands at the end of each leg for the step in which robot-sim ends the go-to (and longer, while the fleet
 * tells the edge, the edge this class, and the next go-to comes back): that step is among the cells it is committed
 * to, so that its plan after the leg starts where it really is. Its next leg is sent when it is seen standing there;
 * a leg queued in robot-sim before would be planned from a poll up to a step old and run off its reservations more
 * often than it saved a step (BENCHMARKS.md, "With the traffic planner").
 * <p>
 * Threads: owned by the robot fleet's thread ({@link RobotFleet}), which calls {@link #step} once per look; the
 * counters are read from any thread.
 */
final class TrafficControl {
    private static final System.Logger LOG = System.getLogger(TrafficControl.class.getName());
    /** Cells a leg runs at most (a longer straight run is sent in pieces: the plan is remade every step). */
    private static final int MAX_LEG = 6;

    private final FleetView view;
    private final RobotCommands commands;
    private final CommandLedgerCounts counts;
    private final int window;
    private final Map<String, Cell> goals = new HashMap<>();
    private FleetPlanner planner;
    private TrafficMap map;
    private String refused;
    private final Map<String, Integer> index = new HashMap<>();
    private final List<String> names = new ArrayList<>();
    /** The end of the leg each robot was last sent on. */
    private final Map<String, Cell> legEnd = new HashMap<>();
    /** When each robot was last sent on a leg (a go-to the edge has not shown yet counts as driven along). */
    private final Map<String, Long> legSince = new HashMap<>();
    private final long pendingNanos;
    /** How long after the edge accepted a leg's go-to the device model may not show it yet; then it is lost. */
    private final long shownWithinNanos;
    /** Robots seen offline and not sent on a leg since (the first leg after is logged: it shows they drive on). */
    private final Set<String> wereOffline = new HashSet<>();
    /** Looks in a row each robot on a leg stood behind another robot. */
    private final Map<String, Integer> blockedLooks = new HashMap<>();
    /** Looks a robot on a leg may stand behind another before its leg is cancelled and planned again. */
    private static final int BLOCKED_LOOKS = 3;
    /**
     * Rounds a robot carrying a cart may go without coming closer to its goal before that goal is checked to be
     * reachable around the carts on the floor (then every as many rounds again): carts put down since the goal was
     * given may wall it in, and the planner would hold the robot for ever.
     */
    static final int WALLED_IN_ROUNDS = 10;
    /** Told the robot and the goal it carries a cart to that no path reaches any more. */
    private final BiConsumer<String, Cell> walledIn;

    /** Counters the report reads (any thread). */
    static final class CommandLedgerCounts {
        final AtomicLong reservedGoTos = new AtomicLong();
        final AtomicLong rounds = new AtomicLong();
        final AtomicLong planNanos = new AtomicLong();
        final AtomicLong cancelledLegs = new AtomicLong();
    }

    /**
     * @param window           steps the planner looks ahead
     * @param pendingNanos     how long a go-to sent may not show in the edge's device model yet, at least
     * @param shownWithinNanos how long after the edge accepted it a go-to may not show in the model yet, at most
     * @param walledIn         told a robot carrying a cart whose goal no path reaches around the carts any more, and
     *                         that goal (on this class's thread)
     */
    TrafficControl(FleetView view, RobotCommands commands, int window, long pendingNanos, long shownWithinNanos,
            BiConsumer<String, Cell> walledIn) {
        this.walledIn = walledIn;
        this.pendingNanos = pendingNanos;
        this.shownWithinNanos = shownWithinNanos;
        this.view = view;
        this.commands = commands;
        this.counts = new CommandLedgerCounts();
        this.window = window;
    }

    CommandLedgerCounts counts() {
        return counts;
    }

    /** The robot's errand goes to this cell now. */
    void goal(String robot, Cell cell) {
        goals.put(robot, cell);
    }

    /** The robot has no goal (docked, errand over): it stays unless it is in someone's way. */
    void clear(String robot) {
        goals.remove(robot);
    }

    /** @return why the planner refuses the warehouse's map, once it is known; empty while it drives */
    Optional<String> refusal() {
        return Optional.ofNullable(refused);
    }

    /** One look: plans every robot and sends the robots standing still on their next legs. */
    void step() {
        Optional<Grid> grid = view.grid();
        List<RobotState> robots = view.robots();
        if (grid.isEmpty() || robots.isEmpty() || refused != null) {
            return;
        }
        if (planner == null || robots.size() != names.size()) {
            start(grid.get(), robots);
            if (refused != null) {
                return;
            }
        }
        Set<Cell> cartCells = view.cartsOnTheFloor();
        boolean[] carts = new boolean[map.cells()];
        cartCells.forEach(c -> carts[map.cell(c)] = true);
        planner.carts(carts);
        Map<String, RobotState> states = new HashMap<>();
        for (RobotState s : robots) {
            Integer r = index.get(s.id());
            if (r == null) {
                continue;
            }
            states.put(s.id(), s);
            if (!s.reachable()) {
                wereOffline.add(s.id());
            }
            Cell goal = goals.get(s.id());
            int at = map.cell(s.cell());
            planner.robot(r, at, goal == null ? FleetPlanner.NO_GOAL : map.cell(goal), s.carrying(), !s.reachable());
            planner.committed(r, onLeg(s));
        }
        long t0 = System.nanoTime();
        planner.plan();
        counts.planNanos.addAndGet(System.nanoTime() - t0);
        counts.rounds.incrementAndGet();
        for (RobotState s : states.values()) {
            if (s.reachable() && !s.idle() && s.facesRobot() && !s.running()) {
                if (!commands.unanswered(s.id()) && blockedLooks.merge(s.id(), 1, Integer::sum) >= BLOCKED_LOOKS) {
                    cancelLeg(s); // its leg met a robot late or early: planned again from where it stands
                }
                continue;
            }
            blockedLooks.remove(s.id());
            Cell end = legEnd.get(s.id());
            boolean legDone = end == null || end.equals(s.cell());
            if (s.reachable() && s.idle() && (legDone || !pending(s))) {
                send(s, planner.path(index.get(s.id())));
            }
        }
        checkWalledIn(states.values(), grid.get(), cartCells);
    }

    /**
     * Carriers that make no progress: each whose goal no path reaches around the carts, or only a way longer than the
     * one through the carts, is told ({@link #walledIn}). The planner's distances see the map without the carts (they
     * are kept per goal for many rounds), so for a carrier two cells from its goal behind a row of carts every cell of
     * the way round looks farther than where it stands, and with the way round longer than the window the planner
     * holds it there for ever.
     */
    private void checkWalledIn(Iterable<RobotState> robots, Grid grid, Set<Cell> carts) {
        for (RobotState s : robots) {
            int stuck = planner.stuck(index.get(s.id()));
            Cell goal = goals.get(s.id());
            if (!s.carrying() || goal == null || goal.equals(s.cell()) || stuck < WALLED_IN_ROUNDS
                    || stuck % WALLED_IN_ROUNDS != 0) {
                continue;
            }
            List<Cell> around = grid.path(s.cell(), goal, carts);
            int through = grid.steps(s.cell(), goal, Set.of());
            if (around == null) {
                LOG.log(System.Logger.Level.WARNING, "{0} carries its cart to {1}, which no path reaches around the"
                        + " carts any more", s.id(), goal);
                walledIn.accept(s.id(), goal);
            } else if (around.size() > through) {
                LOG.log(System.Logger.Level.INFO, "{0} carries its cart to {1}, which the carts on the floor put {2}"
                        + " steps away instead of {3}", s.id(), goal, around.size(), through);
                walledIn.accept(s.id(), goal);
            }
        }
    }

    private void start(Grid grid, List<RobotState> robots) {
        map = TrafficMap.of(grid);
        Optional<String> why = MapCheck.refusal(map, window);
        if (why.isPresent()) {
            refused = why.get();
            LOG.log(System.Logger.Level.ERROR, "the traffic planner refuses this warehouse, no robot is driven: {0}",
                    refused);
            return;
        }
        names.clear();
        index.clear();
        robots.stream().map(RobotState::id).sorted(Comparator.comparingInt(RobotNames::number)
                .thenComparing(Comparator.naturalOrder())).forEach(id -> {
                    index.put(id, names.size());
                    names.add(id);
                });
        planner = new FleetPlanner(map, names.size(), window);
        LOG.log(System.Logger.Level.INFO, "traffic planner: {0} robots, {1}x{2} cells, {3} passages, window {4}",
                names.size(), map.width(), map.height(), map.passages(), window);
    }

    /**
     * The cells still ahead on the leg the robot drives along now (its go-to running), or none; a robot busy with
     * something else (lifting or placing a cart, a go-to not sent by this class) stays where it is for two steps.
     */
    private int[] onLeg(RobotState s) {
        Cell sent = legEnd.get(s.id());
        boolean atGoal = s.cell().equals(goals.get(s.id()));
        if (!s.idle() && (sent == null || !s.headingFor(sent)) || s.idle() && atGoal) {
            // busy, or at its goal where the errand's next command (lift, place) is due: nobody pushes it off
            int here = map.cell(s.cell());
            return new int[] {here, here};
        }
        Cell end = legEnd.get(s.id());
        if (end == null || end.equals(s.cell()) || !s.headingFor(end) && !pending(s)) {
            return new int[0];
        }
        int dx = Integer.signum(end.x() - s.cell().x());
        int dy = Integer.signum(end.y() - s.cell().y());
        if (dx != 0 && dy != 0) {
            return new int[0];
        }
        int n = Math.min(s.cell().distance(end), window);
        // and the step in which robot-sim ends the go-to, at the end, when the window reaches it
        int[] cells = new int[Math.min(n + 1, window)];
        for (int i = 0; i < n; i++) {
            cells[i] = map.cell(s.cell().x() + dx * (i + 1), s.cell().y() + dy * (i + 1));
        }
        if (n < window) {
            cells[n] = map.cell(end);
        }
        return cells;
    }

    private void cancelLeg(RobotState s) {
        blockedLooks.remove(s.id());
        legEnd.remove(s.id());
        legSince.put(s.id(), System.nanoTime());
        counts.cancelledLegs.incrementAndGet();
        CancelMissionCommand cancel = new CancelMissionCommand();
        cancel.deviceId = s.id();
        cancel.missionType = RobotState.GOTO;
        commands.send(cancel, "its leg is blocked by another robot: planned again");
    }

    /**
     * Whether the robot's last leg may not show in the edge's device model yet: its go-to is not answered, or
     * answered as a mission newer than the one the model shows (for {@link #shownWithinNanos} at most), or it was sent
     * so recently that the edge may not show it. A leg sent before the last one shows would be planned from a cell the
     * robot has left and would queue behind the last one: a cancel would then end only the first, and the robot would
     * drive on along the stale one.
     */
    private boolean pending(RobotState s) {
        return commands.goToUnseen(s.id(), s.missionId(), shownWithinNanos)
                || System.nanoTime() - legSince.getOrDefault(s.id(), 0L) < pendingNanos;
    }

    /** Sends the robot on the straight run of moves its plan starts with, if it moves at once. */
    private void send(RobotState s, int[] path) {
        int k = straightRun(path, 0);
        if (k < 0) {
            return; // its plan says wait
        }
        Cell end = map.cell(path[k]);
        if (end.equals(legEnd.get(s.id())) && s.headingFor(end)) {
            return;
        }
        legEnd.put(s.id(), end);
        goTo(s, end);
    }

    /**
     * @return the index in {@code path} of the end of the straight run of moves that starts at {@code from}, at
     *         most {@link #MAX_LEG} cells; -1 when the path waits at {@code from}
     */
    private static int straightRun(int[] path, int from) {
        if (path[from + 1] == path[from]) {
            return -1;
        }
        int step = path[from + 1] - path[from];
        int k = from + 1;
        while (k + 1 < path.length && k - from < MAX_LEG && path[k + 1] - path[k] == step) {
            k++;
        }
        return k;
    }

    private void goTo(RobotState s, Cell end) {
        legSince.put(s.id(), System.nanoTime());
        GoToCommand go = new GoToCommand();
        go.deviceId = s.id();
        go.x = end.x();
        go.y = end.y();
        counts.reservedGoTos.incrementAndGet();
        if (wereOffline.remove(s.id())) {
            LOG.log(System.Logger.Level.INFO, "{0} drives on along its reserved path, back online: to {1}", s.id(),
                    end);
        }
        commands.send(go, "a leg of its reserved path to " + end);
    }

    /** A line of figures for the log (the scenario's report reads the last one). */
    String figures(long goTosSent) {
        long rounds = counts.rounds.get();
        return String.format(java.util.Locale.ROOT, "traffic: %d rounds, planning %.2f ms per round, %d go-tos sent,"
                + " %d along reserved paths, %d robots held, %d legs cancelled (blocked)", rounds,
                rounds == 0 ? 0 : counts.planNanos.get() / 1e6 / rounds, goTosSent, counts.reservedGoTos.get(),
                planner == null ? 0 : planner.fallbacks(), counts.cancelledLegs.get());
    }
}
