package eu.brain.iot.behaviours.robot.impl;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.behaviours.warehouse.CartBudget;
import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.FleetView.CartState;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotState;

/**
 * The errands of every robot and the claim table that keeps two robots from going for the same cart. One table is
 * enough because every robot instance of the model lives in one behaviour component (the generated
 * {@code RobotSmartBehaviour} hosts Robot1..3 of every group), whose extern functions this bundle registers once.
 * <p>
 * The table keeps who does what; each decision is a policy of its own: when a robot may claim a cart
 * ({@link CartRelease}), which cart ({@link CartChoice}), which storage cell once it lifted it ({@link StorageChoice}),
 * and the dock of a robot met out on the floor ({@link DockingWay}). After placing its cart a robot heads for its dock
 * (the docking cell where it was first seen). behaviours/README.md, "Errands", states the rules.
 * <p>
 * Not thread-safe: owned by the robot fleet's thread ({@link RobotFleet}).
 */
final class Errands {

    /** What a robot is doing now. */
    enum Leg { NONE, TO_CART, TO_STORAGE, TO_DOCK }

    /** One robot's errand, a copy (the table keeps its own). */
    record Errand(String robot, Leg leg, String cart, Cell cartCell, Cell drop, Cell dock) {
        /** @return where the errand goes next, or {@code null} when it has none */
        Cell goal() {
            return switch (leg) {
                case TO_CART -> cartCell;
                case TO_STORAGE -> drop;
                case TO_DOCK -> dock;
                case NONE -> null;
            };
        }
    }

    private final Map<String, Errand> errands = new HashMap<>();
    /** When a robot without an errand may claim a cart, and which. */
    private final CartRelease release;
    private final Map<String, Cell> docks = new HashMap<>();
    /**
     * Carts each robot was given (claimed, or carrying or going for one when taken over), counted against the robot
     * model's {@link CartBudget}: a robot given as many is not counted on to take another ({@link EndGame}). A claim
     * planned anew counts twice, which only makes the count err towards a robot having none left.
     */
    private final Map<String, Integer> given = new HashMap<>();
    /** Docks an earlier run of this behaviour learnt ({@link DockBook}): given back to robots met out on the floor. */
    private final Map<String, Cell> remembered = new HashMap<>();
    /** What the instance that drove the fleet before shared ({@link #inherit}), for robots not taken over yet. */
    private ErrandHandover.Table handedOver = ErrandHandover.Table.EMPTY;
    /** The robots this table has taken over ({@link #adopt}): each once. */
    private final Set<String> adopted = new HashSet<>();
    /** Storage cells given to a cart being carried there. */
    private final Set<Cell> drops = new HashSet<>();
    /** Through several doors, which doors a claim may take its cart behind. */
    private final DoorShares doorShares = new DoorShares();
    private int delivered;

    /** @param wave robots that may go for carts at once, in waves (at least 1) */
    Errands(int wave) {
        this(CartRelease.waves(wave));
    }

    /** @param release when a robot without an errand may claim a cart, and which */
    Errands(CartRelease release) {
        this.release = release;
    }

    /** The robot was seen here; the first docking cell it is seen on is its dock. */
    void seen(String robot, Cell cell, boolean docking) {
        if (docking) {
            docks.putIfAbsent(robot, cell);
        }
    }

    /**
     * Takes over a robot the first time this table sees it, from what the robot does now (the device model): on a
     * fresh start every robot is docked and idle, and only its dock is learnt; when the behaviour starts again while
     * the fleet works (stopped, then brought back by the BMS), the errands are rebuilt so that no robot is left
     * without one:
     * <ul>
     * <li>carrying a cart: it carries it to storage (to the storage cell the instance that drove the fleet before
     * gave it ({@link #inherit}), else the one it is heading for, when still free; else one is given as it goes);</li>
     * <li>going for a cart (as that instance said), heading for or standing on one, that no robot claimed: it goes
     * for that cart;</li>
     * <li>anywhere else outside the docking area: it goes home.</li>
     * </ul>
     * A robot's dock is the one that instance knew; else, first seen parked in the docking area, there; first seen
     * elsewhere, or moving, the dock an earlier run learnt for it ({@link #remember}) when that is free, else a free
     * docking cell ({@link #dockFor}).
     *
     * @param s      the robot now
     * @param carts  the carts now
     * @param grid   the map
     * @param robots every robot now (their cells are not free docks)
     * @return whether it was taken over now (its first sight)
     */
    boolean adopt(RobotState s, List<CartState> carts, Grid grid, List<RobotState> robots) {
        String robot = s.id();
        if (!adopted.add(robot)) {
            seen(s, grid);
            return false;
        }
        Cell handedDock = handedOver.docks().get(robot);
        if (handedDock != null && !docks.containsValue(handedDock)) {
            docks.putIfAbsent(robot, handedDock); // the dock the fleet's driver before knew
        } else if (grid.area(s.cell()) == Grid.DOCKING && (s.idle() || !remembered.containsKey(robot))) {
            docks.putIfAbsent(robot, s.cell()); // parked: at its dock (a fresh start)
        } else if (!docks.containsKey(robot)) {
            Cell dock = dockFor(robot, s.cell(), grid, robots);
            if (dock != null) {
                docks.put(robot, dock);
            }
        }
        if (errands.containsKey(robot)) {
            return true;
        }
        Cell dock = docks.get(robot);
        Errand before = handedOver.errands().get(robot);
        given.merge(robot, handedOver.given().getOrDefault(robot, 0), Math::max);
        if (s.carrying()) {
            Cell kept = before != null && before.leg() == Leg.TO_STORAGE ? before.drop() : null;
            Cell heading = !s.idle() ? s.goal() : null;
            Cell drop = freeDrop(kept, carts, grid) ? kept : freeDrop(heading, carts, grid) ? heading : null;
            if (drop != null) {
                drops.add(drop);
            }
            errands.put(robot, new Errand(robot, Leg.TO_STORAGE, s.cart(), null, drop, dock));
            given.merge(robot, before == null ? 1 : 0, Integer::sum);
            return true;
        }
        Cell target = !s.idle() && s.goal() != null ? s.goal() : s.cell();
        String wanted = before != null && before.leg() == Leg.TO_CART ? before.cart() : null;
        Optional<CartState> cart = carts.stream()
                .filter(c -> (c.id().equals(wanted) || c.cell().equals(target)) && waiting(c, grid)
                        && !claimed(c.id()))
                .min(Comparator.comparing(c -> !c.id().equals(wanted))); // the cart it went for first
        if (cart.isPresent()) {
            errands.put(robot, new Errand(robot, Leg.TO_CART, cart.get().id(), cart.get().cell(), null, dock));
            given.merge(robot, wanted == null ? 1 : 0, Integer::sum);
        } else if (grid.area(s.cell()) != Grid.DOCKING && dock != null) {
            errands.put(robot, new Errand(robot, Leg.TO_DOCK, null, null, null, dock));
        }
        return true;
    }

    /** @return whether a robot carrying a cart may put it down there: a storage cell no cart stands on or is given */
    private boolean freeDrop(Cell c, List<CartState> carts, Grid grid) {
        return c != null && grid.area(c) == Grid.STORAGE && !drops.contains(c)
                && carts.stream().noneMatch(x -> x.carriedBy() == null && x.cell().equals(c));
    }

    /**
     * What the instance that drove the fleet before this one shared ({@link ErrandHandover}): the robots this table
     * takes over from now on continue their errands ({@link #adopt}) and keep their docks; until then their carts and
     * storage cells are kept for them (an empty table ends that).
     */
    void inherit(ErrandHandover.Table table) {
        handedOver = table;
    }

    /** @return this table as the instances standing by inherit it ({@link ErrandHandover}) */
    String handover() {
        return ErrandHandover.write(errands.values(), docks, given);
    }

    /** The dock of a robot first met out on the floor ({@link DockingWay#dockFor}). */
    private Cell dockFor(String robot, Cell from, Grid grid, List<RobotState> robots) {
        Set<Cell> taken = new HashSet<>(docks.values());
        remembered.forEach((r, c) -> taken.add(c));
        robots.stream().filter(o -> !o.id().equals(robot)).forEach(o -> taken.add(o.cell()));
        return DockingWay.dockFor(from, remembered.get(robot), new HashSet<>(docks.values()), taken, grid);
    }

    /** Docks an earlier run of this behaviour learnt, for robots not seen yet. */
    void remember(Map<String, Cell> kept) {
        kept.forEach((robot, c) -> {
            if (!adopted.contains(robot)) {
                remembered.put(robot, c);
            }
        });
    }

    /** @return the docks learnt so far, a copy */
    Map<String, Cell> docks() {
        return Map.copyOf(docks);
    }

    /** @return whether {@link #adopt} has taken the robot over already */
    boolean knows(String robot) {
        return adopted.contains(robot);
    }

    /**
     * A robot taken over already, seen again: its dock is learnt as before ({@link #seen(String, Cell, boolean)}),
     * and one standing idle out on the floor without an errand (the orchestrator sent it out of another robot's way)
     * goes home.
     */
    void seen(RobotState s, Grid grid) {
        String robot = s.id();
        boolean docking = grid.area(s.cell()) == Grid.DOCKING;
        seen(robot, s.cell(), docking);
        if (!errands.containsKey(robot) && s.idle() && !docking && docks.containsKey(robot)) {
            errands.put(robot, new Errand(robot, Leg.TO_DOCK, null, null, null, docks.get(robot)));
        }
    }

    Errand of(String robot) {
        return errands.getOrDefault(robot, new Errand(robot, Leg.NONE, null, null, null, docks.get(robot)));
    }

    /**
     * @param parked the cells where other robots stand parked in the docking area (their docks may not be known yet)
     * @return the other robots' docks and {@code parked}: the cells a robot's way in and out of the docking area
     *         avoids ({@link DockingWay})
     */
    Set<Cell> otherDocks(String robot, Set<Cell> parked) {
        Set<Cell> others = new HashSet<>(docks.values());
        others.addAll(parked);
        others.remove(docks.get(robot));
        return others;
    }

    /** @return whether some cart on the floor outside storage is claimed by nobody */
    boolean workLeft(List<CartState> carts, Grid grid) {
        return carts.stream().anyMatch(c -> waiting(c, grid) && !claimed(c.id()));
    }

    /**
     * The door policy ({@link CartRelease}): in waves, a robot may claim a cart while no robot carries one (the wave
     * has not started back: no robot comes up through the door against the robots going down) and fewer than a
     * wave's robots go for carts; once a robot lifts its cart, no new claim until every cart of the wave is placed in
     * storage, then the next wave goes down. Released continuously (the traffic planner), a robot may claim while
     * fewer than its share of robots per door are out on an errand for a cart (going for one or carrying it).
     *
     * @param grid the map (its doors)
     * @return whether a robot without an errand may claim a cart now
     */
    boolean waveOpen(Grid grid) {
        long toCart = errands.values().stream().filter(e -> e.leg() == Leg.TO_CART).count();
        long carrying = errands.values().stream().filter(e -> e.leg() == Leg.TO_STORAGE).count();
        return release.open(toCart, carrying, grid.cells(Grid.DOORWAY).size());
    }

    /** @return whether a robot carrying a cart back may set off now ({@link CartRelease#mayCarryBack}) */
    boolean mayCarryBack(String robot, List<RobotState> robots) {
        return release.mayCarryBack(robot, goingForCarts(), robots);
    }

    /** @return the errands of the robots going for a cart (copies) */
    List<Errand> goingForCarts() {
        return errands.values().stream().filter(e -> e.leg() == Leg.TO_CART).toList();
    }

    /**
     * Claims a waiting cart (which one: {@link CartRelease#order}, {@link CartChoice}; through several doors, behind
     * a door that has fewer robots out than its share, {@link DoorShares}) for a robot without an errand, when the
     * wave is open ({@link #waveOpen}).
     *
     * @param fleet the robots of the fleet
     */
    Optional<Errand> claim(String robot, Cell at, List<CartState> carts, Grid grid, int fleet) {
        return claim(robot, at, carts, grid, fleet, List.of());
    }

    /**
     * As {@link #claim(String, Cell, List, Grid, int)}, knowing where the fleet's robots are: at the end of the work a
     * robot leaves a cart to another that will be done with it sooner ({@link EndGame}).
     *
     * @param robots every robot of the fleet now
     */
    Optional<Errand> claim(String robot, Cell at, List<CartState> carts, Grid grid, List<RobotState> robots) {
        return claim(robot, at, carts, grid, robots.size(), robots);
    }

    private Optional<Errand> claim(String robot, Cell at, List<CartState> carts, Grid grid, int fleet,
            List<RobotState> robots) {
        if (!waveOpen(grid)) {
            return Optional.empty();
        }
        int doors = grid.cells(Grid.DOORWAY).size();
        List<CartState> candidates = carts.stream().filter(c -> waiting(c, grid) && !claimed(c.id())).toList();
        CartChoice.Order order = release.order(doors);
        if (order == CartChoice.Order.DEEPEST_BEHIND_NEAREST_DOOR) {
            List<Cell> out = errands.values().stream()
                    .filter(x -> (x.leg() == Leg.TO_CART || x.leg() == Leg.TO_STORAGE) && x.cartCell() != null)
                    .map(Errand::cartCell).toList();
            candidates = doorShares.behindOpenDoors(candidates, out,
                    (int) Math.min(fleet, release.robotsOut(doors)), grid);
        }
        Cell dock = docks.get(robot);
        if (dock != null && dock.equals(at) && !robots.isEmpty()) {
            candidates = EndGame.worthTaking(dock, candidates, others(robot, robots), doorShares, grid);
        }
        Optional<CartState> chosen = CartChoice.choose(at, candidates, grid, order);
        if (chosen.isEmpty()) {
            return Optional.empty();
        }
        CartState best = chosen.get();
        Errand e = new Errand(robot, Leg.TO_CART, best.id(), best.cell(), null, docks.get(robot));
        errands.put(robot, e);
        given.merge(robot, 1, Integer::sum);
        return Optional.of(e);
    }

    /**
     * The fleet's other robots that may take another cart (a dock, a current state, carts left in their budget), and
     * when each will be back at its dock.
     */
    private List<EndGame.Other> others(String robot, List<RobotState> robots) {
        List<EndGame.Other> others = new ArrayList<>(robots.size());
        for (RobotState s : robots) {
            Cell dock = docks.get(s.id());
            if (s.id().equals(robot) || dock == null || !s.reachable()
                    || given.getOrDefault(s.id(), 0) >= CartBudget.PER_ROBOT) {
                continue;
            }
            Errand e = errands.get(s.id());
            Cell via = e == null ? null : switch (e.leg()) {
                case TO_CART -> e.cartCell();
                case TO_STORAGE -> e.drop();
                case NONE, TO_DOCK -> null;
            };
            others.add(new EndGame.Other(dock, EndGame.stepsUntilBack(s.cell(), via, dock)));
        }
        return others;
    }

    /** The robot lifted its cart: it is given a storage cell, or none when no free one can be reached. */
    Optional<Errand> lifted(String robot, Cell at, List<CartState> carts, Grid grid) {
        Errand e = of(robot);
        if (e.drop() != null) {
            drops.remove(e.drop()); // chosen again, with what the warehouse looks like now
        }
        Set<Cell> walls = new HashSet<>(drops); // storage cells given to carts, carried there or put down
        walls.addAll(handedOver.heldDrops(adopted));
        carts.stream().filter(c -> c.carriedBy() == null).forEach(c -> walls.add(c.cell()));
        walls.remove(at); // the cart it lifts
        List<Cell> inFlight = errands.values().stream().filter(x -> x.leg() == Leg.TO_STORAGE && x.drop() != null
                && !x.robot().equals(robot)).map(Errand::drop).toList();
        Cell best = StorageChoice.choose(grid, at, e.dock(), walls, inFlight);
        if (best == null) {
            errands.put(robot, new Errand(robot, Leg.TO_STORAGE, e.cart(), e.cartCell(), null, e.dock()));
            return Optional.empty(); // asked again when the robot goes on (a placed cart may free the way)
        }
        drops.add(best);
        Errand next = new Errand(robot, Leg.TO_STORAGE, e.cart(), e.cartCell(), best, e.dock());
        errands.put(robot, next);
        return Optional.of(next);
    }

    /**
     * A go-to of the robot's errand failed when it started (robot-sim: no path, e.g. a cart put down since on the
     * storage cell it was given, which the device model did not show yet): the errand's goal is chosen again, so
     * the robot is never sent to the same unreachable cell over and over. A storage cell is given anew, avoiding
     * that cell; a cart that cannot be reached goes back to the table.
     *
     * @return whether the errand changed
     */
    boolean goalFailed(String robot, Cell at, Cell goal, List<CartState> carts, Grid grid) {
        Errand e = errands.get(robot);
        if (e == null || goal == null || !goal.equals(e.goal())) {
            return false;
        }
        switch (e.leg()) {
            case TO_STORAGE -> {
                drops.remove(e.drop());
                drops.add(goal); // kept out of the choice below, then given back
                errands.put(robot, new Errand(robot, Leg.TO_STORAGE, e.cart(), e.cartCell(), null, e.dock()));
                lifted(robot, at, carts, grid); // none found: asked again as the robot goes on
                drops.remove(goal);
                return true;
            }
            case TO_CART -> {
                errands.remove(robot);
                return true;
            }
            default -> {
                return false;
            }
        }
    }

    /**
     * The robot carries its cart to a storage cell it can no longer reach around the carts on the floor, or only the
     * long way round (carts put down since walled that cell, or the robot, in; the traffic planner finds no path there
     * and no go-to fails to say so): it is given another storage cell it can reach from where it stands, chosen as at
     * the lift ({@link #goalFailed}, {@link StorageChoice}), and when there is none but it stands on a free storage
     * cell, that cell: its cart is in storage either way.
     *
     * @return whether the errand changed
     */
    boolean walledIn(String robot, Cell at, Cell drop, List<CartState> carts, Grid grid) {
        if (!goalFailed(robot, at, drop, carts, grid)) {
            return false;
        }
        Errand e = errands.get(robot);
        boolean free = carts.stream().noneMatch(c -> c.carriedBy() == null && c.cell().equals(at));
        if (e.drop() == null && grid.area(at) == Grid.STORAGE && free && !drops.contains(at)) {
            drops.add(at);
            errands.put(robot, new Errand(robot, Leg.TO_STORAGE, e.cart(), e.cartCell(), at, e.dock()));
        }
        return true;
    }

    /**
     * The robot's cart is on the floor although its errand says it carries it (put down just before this
     * behaviour took the robot over, or its pick failed): in storage it counts as placed and the robot heads home;
     * elsewhere the cart goes back to the table.
     */
    void cartDown(String robot, Cell at, Grid grid) { // at: where the cart stands
        Errand e = errands.get(robot);
        if (e == null || e.leg() != Leg.TO_STORAGE) {
            return;
        }
        if (grid.area(at) == Grid.STORAGE) {
            if (e.drop() != null && !e.drop().equals(at)) {
                drops.remove(e.drop());
            }
            drops.add(at);
            placed(robot);
        } else {
            // the cart stands outside storage, not carried: back on the table for any robot to fetch (keeping the
            // errand would have the robot "carry" a cart it does not hold, planned anew at every look)
            if (e.drop() != null) {
                drops.remove(e.drop());
            }
            errands.remove(robot);
        }
    }

    /** The robot put its cart down in storage: it heads home. */
    Errand placed(String robot) {
        Errand e = of(robot);
        delivered++;
        Errand next = new Errand(robot, Leg.TO_DOCK, null, null, null, e.dock());
        errands.put(robot, next);
        return next;
    }

    /** Going home, it still carries its cart (the place was lost): not delivered; it carries it to storage again. */
    void carryBack(String robot, String cart) {
        delivered--;
        errands.put(robot, new Errand(robot, Leg.TO_STORAGE, cart, null, null, of(robot).dock()));
    }

    /** The robot is back at its dock: no errand. */
    void docked(String robot) {
        errands.remove(robot);
    }

    /**
     * The robot's errand is planned anew (its commands were refused): going for a cart, it gives the cart back to the
     * table (it cannot fetch it; another robot may claim it); carrying one, it keeps it and its storage cell is chosen
     * again as it goes (only it can bring that cart to storage); going home, it goes on home.
     */
    void release(String robot) {
        Errand e = errands.get(robot);
        if (e == null) {
            return;
        }
        if (e.drop() != null) {
            drops.remove(e.drop());
        }
        switch (e.leg()) {
            case TO_STORAGE -> errands.put(robot, new Errand(robot, Leg.TO_STORAGE, e.cart(), e.cartCell(), null,
                    e.dock()));
            case TO_DOCK -> {
                // still on its way home
            }
            default -> errands.remove(robot);
        }
    }

    int delivered() {
        return delivered;
    }

    /** @return whether a robot has an errand for this cart */
    boolean claimed(String cart) {
        return errands.values().stream().anyMatch(e -> cart.equals(e.cart())) || handedOver.holds(cart, adopted);
    }

    /** A cart on the floor and not in storage waits for a robot. */
    private static boolean waiting(CartState c, Grid grid) {
        return c.carriedBy() == null && grid.area(c.cell()) != Grid.STORAGE;
    }
}
