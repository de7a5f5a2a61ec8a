package eu.brain.iot.behaviours.orchestrator.impl;

import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.behaviours.warehouse.FleetView;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotNames;
import eu.brain.iot.behaviours.warehouse.RobotState;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.eventing.api.EventBus;

/**
 * The orchestrator's geometry (the paper's "AI algorithms" behind resolvedPosition1..3), from the edge's device
 * model (every robot's cell, heading, cart and goal; the map). For a robot R stopped behind a robot F (the robot in
 * the cell R faces):
 * <ul>
 * <li>F is not blocked by R (F moves on, waits at a door, lifts or places a cart, or waits behind another robot):
 * R waits: it gets its own position, which its behaviour reads as "go on" once the way is clear;</li>
 * <li>F stands still with nothing to do (a robot parked in the way): F is sent to the nearest free cell off R's
 * path (a go-to the orchestrator sends itself; F's behaviour has no errand to disturb), and R waits; under the
 * fleet's traffic planner ({@link FleetMode#traffic}) R only waits: the planner pushes F or plans R around it, and
 * a go-to of the orchestrator's own would run off the reserved paths;</li>
 * <li>F faces R (head-on, which the fleet's own rules leave deadlocked): one of them yields, the robot without a
 * cart to the robot carrying one, else the robot with the higher number. The yielding robot gets the nearest free
 * cell off the other's path (searched through free cells; not a doorway; for a robot carrying a cart, not under
 * another cart; reached by a shortest path that meets no robot), encoded as {@code -(1 + x + 1000 y)}; the other
 * waits and drives on once it is clear. When the robot that should yield has no such cell, the other steps aside
 * instead if it has one.</li>
 * </ul>
 * Each robot's answer depends only on the pair, so two robots that report the same meeting at different times
 * get answers that agree. Thread-safe: the view and ledger are; no other state.
 */
@Component(service = CollisionGeometry.class, configurationPid = FleetMode.PID)
public final class CollisionGeometry {

    private static final System.Logger LOG = System.getLogger(CollisionGeometry.class.getName());

    private final FleetView view;
    private final CommandLedger ledger;
    /** Whether the traffic planner drives the robots: no robot is sent anywhere from here. */
    private final boolean traffic;

    @Activate
    public CollisionGeometry(@Reference DeviceModel model, @Reference EventBus bus, FleetMode mode) {
        this.view = new FleetView(model);
        this.ledger = new CommandLedger(bus, "orchestrator-");
        this.traffic = mode.traffic();
        LOG.log(System.Logger.Level.INFO, traffic ? "the traffic planner drives the robots: a robot parked in the way"
                + " of another is left to it" : "a robot parked in the way of another is sent aside");
    }

    /**
     * @param robot    the fleet's id of a robot that reported a robot in front
     * @param position its reported position (an area code)
     * @return its resolved position: {@code position} (wait, then go on) or a side cell, encoded
     */
    double resolve(String robot, double position) {
        Optional<RobotState> me = view.robot(robot);
        Optional<Grid> grid = view.grid();
        if (me.isEmpty() || grid.isEmpty()) {
            return position;
        }
        List<RobotState> robots = view.robots();
        RobotState r = me.get();
        Optional<RobotState> front = robots.stream().filter(o -> o.cell().equals(r.ahead())).findFirst();
        if (front.isEmpty()) {
            return position; // the way cleared meanwhile
        }
        RobotState f = front.get();
        if (f.idle() && !f.running()) {
            Cell aside = traffic ? null : freeCellOffPath(grid.get(), f, r, robots);
            if (aside != null) {
                LOG.log(System.Logger.Level.INFO, "{0} is parked in the way of {1}: sent to {2}", f.id(), r.id(),
                        aside);
                GoToCommand go = new GoToCommand();
                go.deviceId = f.id();
                go.x = aside.x();
                go.y = aside.y();
                try {
                    ledger.send(go, "clearing the way of " + r.id());
                } catch (RuntimeException e) {
                    LOG.log(System.Logger.Level.WARNING, "{0} not sent aside: {1}", f.id(), e.getMessage());
                }
            }
            return position;
        }
        if (!f.ahead().equals(r.cell())) {
            return position; // not head-on: traffic, the robot waits
        }
        if (!yields(r, f) && freeCellOffPath(grid.get(), f, r, robots) != null) {
            return position; // the other yields
        }
        // r yields, or the other should but has no free cell to go to: then r steps aside if it can
        Cell aside = freeCellOffPath(grid.get(), r, f, robots);
        if (aside == null) {
            LOG.log(System.Logger.Level.WARNING, "{0} should yield to {1} but has no free cell to go to; it waits",
                    r.id(), f.id());
            return position;
        }
        LOG.log(System.Logger.Level.INFO, "{0} and {1} meet head-on: {0} steps aside to {2}", r.id(), f.id(), aside);
        return encode(aside);
    }

    /** @return whether the shortest path from {@code from} to {@code to} (around carts, if given) meets no robot */
    private static boolean clearWay(Grid grid, Cell from, Cell to, Set<Cell> occupied, Set<Cell> carts) {
        List<Cell> path = grid.path(from, to, carts);
        return path != null && path.stream().noneMatch(occupied::contains);
    }

    /** @return whether {@code r} yields to {@code f}: no cart against a cart, else the higher number yields */
    static boolean yields(RobotState r, RobotState f) {
        if (r.carrying() != f.carrying()) {
            return !r.carrying();
        }
        int rk = RobotNames.number(r.id());
        int fk = RobotNames.number(f.id());
        return rk != fk ? rk > fk : r.id().compareTo(f.id()) > 0;
    }

    static double encode(Cell c) {
        return -(1 + c.x() + 1000.0 * c.y());
    }

    /** The nearest free cell for {@code mover}, off the path of {@code other} to its goal (or its way ahead). */
    private Cell freeCellOffPath(Grid grid, RobotState mover, RobotState other, List<RobotState> robots) {
        Set<Cell> occupied = new HashSet<>();
        robots.forEach(o -> occupied.add(o.cell()));
        Set<Cell> otherPath = new HashSet<>();
        otherPath.add(other.cell());
        if (other.goal() != null) {
            List<Cell> p = grid.path(other.cell(), other.goal(), Set.of());
            if (p != null) {
                otherPath.addAll(p);
            }
        }
        Cell c = other.cell().toward(other.heading());
        while (grid.passable(c)) { // and every cell straight ahead of it up to a wall, whatever its goal
            otherPath.add(c);
            c = c.toward(other.heading());
        }
        Set<Cell> cartCells = mover.carrying() ? view.cartsOnTheFloor() : Set.of();
        // and a cell the mover's own planner (a shortest path, robots ignored) reaches without meeting a robot
        java.util.function.Predicate<Cell> free = cell -> !otherPath.contains(cell) && !occupied.contains(cell)
                && grid.area(cell) != Grid.DOORWAY && !cartCells.contains(cell)
                && clearWay(grid, mover.cell(), cell, occupied, cartCells);
        // a cell of the mover's own area first (a parked robot stays in docking), else any
        Cell same = grid.nearest(mover.cell(), free.and(cell -> grid.area(cell) == mover.area()), occupied);
        return same != null ? same : grid.nearest(mover.cell(), free, occupied);
    }
}
