package eu.brain.iot.behaviours.robot.impl;

import java.io.File;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.behaviours.warehouse.BindingThread;
import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.behaviours.warehouse.FleetView;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;
import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.eventing.api.EventBus;

/**
 * What the robot model's steps do to the fleet, and the only place that sends robots commands: each
 * command is an edge command event on the bus with a commandId ({@link CommandLedger}), one robot's commands in
 * the order given ({@link RobotCommands}: the next once the edge answered the one before), and each outcome is
 * checked ({@link Refusals}): a refusal is logged with the robot and the reason, counted, sent again up to
 * {@code command.retries} times, then the errand is planned anew (the cart goes back to the claim table). Where
 * the errands go is the {@link Errands} table's; where the robots and carts are, the edge's device model's.
 * <p>
 * Threads: the fleet's state (errands, pending go-tos, robots aside, refusals, the traffic planner) has one owner,
 * the fleet's thread ({@link #thread()}), on which the binding looks at the robots, handles the edge's events and
 * applies the steps the model instances' hosts report ({@link ModelStep}: {@link #resume}, {@link #sideStep},
 * {@link #lift}, {@link #place}). Read from any thread: the device model ({@link #area}) and the counters.
 */
@Component(service = RobotFleet.class, configurationPid = RobotConfig.PID)
public final class RobotFleet {

    private static final System.Logger LOG = System.getLogger(RobotFleet.class.getName());
    /** Polls after its acceptance within which a leg's go-to shows in the device model, or is taken as lost. */
    private static final int SHOWN_WITHIN_POLLS = 20;

    private final FleetView view;
    private final CommandLedger ledger;
    private final RobotCommands commands;
    private final Errands errands;
    /** Owns the fleet's state: the binding's looks and events, and the extern functions' effects. */
    private final BindingThread thread;

    // the fleet's thread only
    /**
     * The goal of the last go-to sent to each robot and when, until that mission ends (so it is never sent twice);
     * one the robot does not show after {@link #pendingNanos} is taken as lost (its end was missed).
     */
    private final Map<String, SentGoal> sentGoal = new HashMap<>();
    private final long pendingNanos;

    private record SentGoal(Cell goal, long atNanos) {
    }

    /** The robots told to step aside, each until it is done waiting there. */
    private final SideSteps aside;
    /** What follows a refused command: sent again, or the errand planned anew. */
    private final Refusals refusals;
    /** Go-tos sent to robots, along reserved paths or not. */
    private final AtomicLong goTos = new AtomicLong();
    /** The traffic planner's driver, or null when robot-sim plans the go-tos ({@code traffic} false). */
    private final TrafficControl traffic;
    private long lastFigures;
    /** The docks learnt, kept for a run of this behaviour started again, and the map they were read for. */
    static final String DOCK_BOOK = "docks.tsv";
    private final DockBook book;
    private Grid bookOf;
    /** The errand table shared with the instances standing by, and the one inherited from the fleet's driver. */
    private final ErrandHandover handover;

    @Activate
    public RobotFleet(@Reference DeviceModel model, @Reference EventBus bus, @Reference FleetLeadership leadership,
            RobotConfig config, BundleContext context) {
        this.view = new FleetView(model);
        this.handover = leadership.handover();
        File data = context == null ? null : context.getDataFile(DOCK_BOOK);
        this.book = new DockBook(data == null ? null : data.toPath());
        this.ledger = new CommandLedger(bus, "robot-behaviour-");
        this.commands = new RobotCommands(ledger);
        this.errands = new Errands(
                config.traffic() ? CartRelease.continuous(config.traffic_release_robots_per_door())
                        : CartRelease.waves(config.wave_robots()));
        this.refusals = new Refusals(commands, ledger, config.command_retries(), Refusals.ANSWER_TIMEOUT_NANOS,
                robot -> {
                    sentGoal.remove(robot);
                    errands.release(robot);
                });
        double speed = config.speed() > 0 ? config.speed() : 1;
        long pollNanos = (long) (TimeUnit.MILLISECONDS.toNanos(config.poll_period_ms()) / speed);
        this.pendingNanos = pollNanos * 8;
        this.traffic = config.traffic()
                ? new TrafficControl(view, commands, Math.max(2, config.traffic_window()), pollNanos * 4,
                        pollNanos * SHOWN_WITHIN_POLLS, this::walledIn) : null;
        this.aside = new SideSteps(pollNanos * 20); // 20 polls of warehouse time at most
        this.thread = new BindingThread("robot-fleet", config.speed(), config.poll_period_ms());
    }

    @Deactivate
    void deactivate() {
        thread.close();
    }

    /** @return the thread that owns the fleet's state, on which the binding runs its looks and handles events */
    BindingThread thread() {
        return thread;
    }

    FleetView view() {
        return view;
    }

    Errands errands() {
        return errands;
    }

    /**
     * The robot as the errand table first sees it (its dock, or the errand it is on when this behaviour started
     * while the fleet worked: {@link Errands#adopt}); later, where it is.
     */
    void adopt(RobotState s) {
        Optional<Grid> grid = view.grid();
        if (grid.isEmpty()) {
            errands.seen(s.id(), s.cell(), s.area() == Grid.DOCKING);
            return;
        }
        if (bookOf != grid.get()) {
            bookOf = grid.get();
            errands.remember(book.load(grid.get()));
        }
        if (handover.holdEnded(System.nanoTime())) {
            errands.inherit(ErrandHandover.Table.EMPTY); // robots not polled since: their carts go back to the table
        }
        if (errands.knows(s.id())) {
            errands.seen(s, grid.get()); // every look at every robot: no read of the other robots and carts
            return;
        }
        ErrandHandover.Table inherited = handover.take(grid.get());
        if (inherited != null) {
            errands.inherit(inherited); // this instance takes the fleet over from the one that drove it
        }
        if (errands.adopt(s, view.carts(), grid.get(), view.robots())) {
            book.save(grid.get(), errands.docks());
            Errands.Errand e = errands.of(s.id());
            if (e.leg() != Errands.Leg.NONE) {
                LOG.log(System.Logger.Level.INFO, "{0} taken over at {1}: {2}{3}, dock {4}", s.id(), s.cell(),
                        e.leg(), e.cart() == null ? "" : " with " + e.cart(), e.dock());
            }
        }
    }

    /**
     * Whether the cart the robot's errand says it carries is on the floor, put down by it: the robot stands idle and
     * empty, the cart on the floor, and no pick this behaviour sent to the robot is still to show in the device model
     * (right after a pick is sent the robot stands on its cart, idle and empty). This covers a place that finished, a
     * pick that failed, and a robot taken over while placing, whatever it was told after.
     *
     * @return the cell of the cart on the floor, or {@code null}
     */
    Cell cartPutDown(RobotState s, Errands.Errand e) {
        if (!s.idle() || s.carrying() || e.cart() == null || commands.pickUnseen(s.id(), s.missionId())) {
            return null;
        }
        return view.carts().stream().filter(c -> c.id().equals(e.cart()) && c.carriedBy() == null)
                .map(c -> c.cell()).findFirst().orElse(null);
    }

    /** @return the area code of the robot's cell (docking 1, unload 2, storage 3), docking when unknown */
    double area(String robot) {
        return view.robot(robot).map(s -> s.area()).filter(RobotExterns::inModelArea).orElse(Grid.DOCKING);
    }

    /**
     * The robot goes on with its errand: a robot without one claims a cart (or heads home when none is left); the
     * go-to is sent unless the robot is there or already on its way.
     */
    void resume(String robot, String why) {
        Optional<RobotState> state = view.robot(robot);
        Optional<Grid> grid = view.grid();
        if (state.isEmpty() || grid.isEmpty()) {
            LOG.log(System.Logger.Level.WARNING, "{0}: cannot go on ({1}): the edge does not know {2} yet", robot, why,
                    state.isEmpty() ? "the robot" : "the warehouse's map");
            return;
        }
        RobotState s = state.get();
        if (aside.holds(s, view::robot)) {
            return; // on its way aside, or waiting there until the robot it let pass is gone
        }
        adopt(s);
        Errands.Errand e = errands.of(robot);
        Cell down = e.leg() == Errands.Leg.TO_STORAGE ? cartPutDown(s, e) : null;
        if (down != null) {
            errands.cartDown(robot, down, grid.get());
            LOG.log(System.Logger.Level.INFO, "{0} carries no cart: {1} stands at {2}, {3}", robot, e.cart(), down,
                    grid.get().area(down) == Grid.STORAGE ? "in storage: the robot goes home"
                            : "not in storage: it goes back to the table");
            e = errands.of(robot);
        }
        if (e.leg() == Errands.Leg.NONE) {
            e = errands.claim(robot, s.cell(), view.carts(), grid.get(), view.robots()).orElse(e);
            if (e.leg() == Errands.Leg.TO_CART) {
                LOG.log(System.Logger.Level.INFO, "{0} goes for {1} at {2}", robot, e.cart(), e.cartCell());
            }
        }
        if (e.leg() == Errands.Leg.TO_STORAGE && e.drop() == null) {
            e = errands.lifted(robot, s.cell(), view.carts(), grid.get()).orElse(e); // a storage cell at last?
        }
        Cell goal = e.goal() != null ? e.goal() : e.leg() == Errands.Leg.TO_STORAGE ? null : e.dock();
        if (e.leg() == Errands.Leg.TO_STORAGE && !mayCarryBack(robot)) {
            return; // the wave's last robots still come down through the door: it waits with its cart
        }
        if (goal != null) {
            goTo(robot, s, homeward(robot, s, goal, grid.get()), why);
        }
    }

    /**
     * The way in and out of the docking area ({@link DockingWay}), without the traffic planner: at the end of each
     * straight leg the binding finds the robot idle before its goal and sends it on. Any other goal is kept.
     */
    private Cell homeward(String robot, RobotState s, Cell goal, Grid grid) {
        Cell dock = errands.of(robot).dock();
        if (traffic != null || !DockingWay.concerns(s.cell(), goal, dock, grid)) {
            return goal; // the other robots are read only for a way in or out of the docking area
        }
        // the others parked in the docking area: at the start, before every robot was seen, their docks are unknown
        Set<Cell> parked = new HashSet<>();
        view.robots().stream().filter(o -> !o.id().equals(robot) && o.idle() && grid.area(o.cell()) == Grid.DOCKING)
                .forEach(o -> parked.add(o.cell()));
        return DockingWay.next(s.cell(), goal, dock, grid, errands.otherDocks(robot, parked));
    }

    /**
     * The orchestrator told the robot to step aside to a cell: its go-to is cancelled, then it goes there, and it
     * waits there while the robot it let pass (the one in front of it now) is within two cells and still moving.
     */
    void sideStep(String robot, Cell cell) {
        if (traffic != null) {
            resume(robot, "after a meeting (the traffic planner routes it)");
            return;
        }
        String passer = view.robot(robot).flatMap(me -> view.robots().stream()
                .filter(o -> o.cell().equals(me.ahead())).map(RobotState::id).findFirst()).orElse(null);
        aside.told(robot, cell, passer);
        CancelMissionCommand cancel = new CancelMissionCommand();
        cancel.deviceId = robot;
        cancel.missionType = RobotState.GOTO;
        commands.send(cancel, "stepping aside to " + cell);
        sentGoal.remove(robot);
        GoToCommand go = new GoToCommand();
        go.deviceId = robot;
        go.x = cell.x();
        go.y = cell.y();
        goTos.incrementAndGet();
        commands.send(go, "stepping aside to " + cell);
    }

    /** The robot stands under its cart: lift it, then head for the storage cell it is given. */
    void lift(String robot) {
        Optional<RobotState> s = view.robot(robot);
        if (s.isPresent() && s.get().carrying()) {
            // taken over carrying its cart (Errands#adopt): the model goes through CART, the robot has it already
            LOG.log(System.Logger.Level.INFO, "{0} already carries {1}", robot, s.get().cart());
        } else {
            PickCartCommand pick = new PickCartCommand();
            pick.deviceId = robot;
            commands.send(pick, "lifting " + errands.of(robot).cart());
        }
        Optional<Grid> grid = view.grid();
        if (s.isEmpty() || grid.isEmpty()) {
            return;
        }
        Optional<Errands.Errand> e = errands.lifted(robot, s.get().cell(), view.carts(), grid.get());
        if (e.isEmpty()) {
            LOG.log(System.Logger.Level.WARNING, "{0}: no free storage cell can be reached with a cart; it waits",
                    robot);
            return;
        }
        sentGoal.remove(robot);
        if (!mayCarryBack(robot)) {
            LOG.log(System.Logger.Level.INFO, "{0} waits with {1} until the wave''s robots are down", robot,
                    e.get().cart());
            return; // the binding sends it on (resume) once they are
        }
        goTo(robot, s.get(), e.get().drop(), "carrying " + e.get().cart() + " to storage");
    }

    /** The robot is at its storage cell: put the cart down, then head for its dock. */
    void place(String robot) {
        PlaceCartCommand place = new PlaceCartCommand();
        place.deviceId = robot;
        commands.send(place, "placing its cart in storage");
        Errands.Errand e = errands.placed(robot);
        Optional<RobotState> s = view.robot(robot);
        sentGoal.remove(robot);
        Optional<Grid> grid = view.grid();
        if (e.dock() != null && s.isPresent() && grid.isPresent()) {
            goTo(robot, s.get(), homeward(robot, s.get(), e.dock(), grid.get()), "going home");
        }
    }

    /** @return whether a place sent to the robot has not shown in the device model yet */
    boolean placeUnseen(RobotState s) {
        return commands.placeUnseen(s.id(), s.missionId());
    }

    /** The robot goes home with its cart, its place lost ({@link Recovery#carryingHome}): it carries it back. */
    void carryBack(RobotState s, String why) {
        LOG.log(System.Logger.Level.WARNING, "{0} is {1}: it carries it to storage again", s.id(), why);
        errands.carryBack(s.id(), s.cart());
    }

    /** @return whether a cart on the floor outside storage waits for a robot (false until the map is known) */
    boolean workLeft() {
        Optional<Grid> grid = view.grid();
        return grid.isPresent() && errands.workLeft(view.carts(), grid.get());
    }

    /** @return whether a robot carrying a cart back may set off now ({@link CartRelease#mayCarryBack}) */
    boolean mayCarryBack(String robot) {
        return errands.mayCarryBack(robot, view.robots());
    }

    /** @return whether a robot without an errand may set off now: a cart waits and the wave is open */
    boolean mayStart() {
        Optional<Grid> grid = view.grid();
        return grid.isPresent() && errands.waveOpen(grid.get()) && workLeft();
    }

    /** A mission of the robot ended: a go-to to the goal last sent is no longer pending. */
    void missionEnded(String robot, String type, Integer goalX, Integer goalY) {
        SentGoal sent = sentGoal.get(robot);
        if (RobotState.GOTO.equals(type) && sent != null && goalX != null
                && sent.goal().equals(new Cell(goalX, goalY == null ? -1 : goalY))) {
            sentGoal.remove(robot);
        }
    }

    /**
     * Under the traffic planner: the robot carries its cart to a storage cell no path reaches around the carts any
     * more, or only the long way round, which the planner does not see ({@link TrafficControl#WALLED_IN_ROUNDS}); it
     * is given another ({@link Errands#walledIn}) and goes on.
     */
    private void walledIn(String robot, Cell drop) {
        Optional<RobotState> s = view.robot(robot);
        Optional<Grid> grid = view.grid();
        if (s.isEmpty() || grid.isEmpty() || !errands.walledIn(robot, s.get().cell(), drop, view.carts(), grid.get())) {
            return;
        }
        Cell next = errands.of(robot).drop();
        LOG.log(System.Logger.Level.WARNING, "{0}: now to {1}", robot,
                next != null ? next : "a storage cell chosen as it goes");
        resume(robot, "its storage cell walled in by carts");
    }

    /**
     * A mission of the robot failed (not cancelled): a go-to to its errand's goal that failed has that goal chosen
     * again ({@link Errands#goalFailed}); then the robot goes on with its errand.
     */
    void missionFailed(String robot, String type, Integer goalX, Integer goalY, String reason) {
        missionEnded(robot, type, goalX, goalY);
        Optional<RobotState> s = view.robot(robot);
        Optional<Grid> grid = view.grid();
        if (RobotState.GOTO.equals(type) && goalX != null && goalY != null && s.isPresent() && grid.isPresent()
                && errands.goalFailed(robot, s.get().cell(), new Cell(goalX, goalY), view.carts(), grid.get())) {
            Errands.Errand e = errands.of(robot);
            LOG.log(System.Logger.Level.WARNING, "{0}: its go-to to ({1},{2}) failed ({3}); {4}", robot, goalX, goalY,
                    reason, e.leg() == Errands.Leg.NONE ? "its cart goes back to the table"
                            : "now " + e.leg() + " " + (e.goal() == null ? "(a cell chosen as it goes)" : e.goal()));
        } else {
            LOG.log(System.Logger.Level.WARNING, "{0}: {1} mission failed ({2}); it goes on with its errand", robot,
                    type, reason);
        }
        resume(robot, "after a failed " + type);
    }

    /** An outcome arrived on the bus ({@link Refusals#outcome}). */
    void outcome(CommandOutcome o) {
        refusals.outcome(o);
    }

    /** On the binding's look: a command left without an outcome counts as refused ({@link Refusals}). */
    void expireUnanswered() {
        refusals.expireUnanswered();
    }

    /** The robot appeared on the node that polls it now: commands it left unanswered went with the one before. */
    void handedOver(String robot) {
        refusals.handedOver(robot);
    }

    /** One look of the binding (its thread): the traffic planner plans and sends legs; figures logged now and then. */
    void trafficStep() {
        if (traffic == null) {
            return;
        }
        traffic.step();
        long now = System.nanoTime();
        if (now - lastFigures > pendingNanos * 3) {
            lastFigures = now;
            LOG.log(System.Logger.Level.INFO, traffic.figures(goTos.get() + traffic.counts().reservedGoTos.get()));
        }
    }

    private void goTo(String robot, RobotState s, Cell goal, String why) {
        if (traffic != null) {
            traffic.goal(robot, goal); // the planner sends it along its reserved path, leg by leg
            return;
        }
        SentGoal sent = sentGoal.get(robot);
        boolean pending = sent != null && sent.goal().equals(goal) && System.nanoTime() - sent.atNanos() < pendingNanos;
        if (s.cell().equals(goal) && s.idle() || s.headingFor(goal) || pending) {
            return; // there, or on its way: a go-to is never sent twice
        }
        GoToCommand go = new GoToCommand();
        go.deviceId = robot;
        go.x = goal.x();
        go.y = goal.y();
        sentGoal.put(robot, new SentGoal(goal, System.nanoTime()));
        goTos.incrementAndGet();
        commands.send(go, why);
    }
}
