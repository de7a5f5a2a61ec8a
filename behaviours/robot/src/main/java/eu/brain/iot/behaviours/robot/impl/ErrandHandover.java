package eu.brain.iot.behaviours.robot.impl;

import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Supplier;
import java.util.regex.Pattern;

import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.Grid;

/**
 * What the instance that drives the fleet tells the instances standing by, so that the one that takes over continues
 * the errands rather than rebuilding them from the device model alone: a robot going for a cart keeps going for it
 * (the device model shows only the end of its current leg, not the cart), one carrying a cart keeps its storage cell,
 * and every robot keeps its dock (a standby's node never saw the robots parked). It rides on the leader's beats
 * ({@link RobotBehaviourAlive#errands}), so a standby is at most one beat behind.
 * <p>
 * Text format, one robot per line: {@code <robot> <dock> <given> <leg> <cart> <cart cell> <storage cell>}, a cell as
 * {@code x,y}, {@code -} for none; e.g. {@code robot7 3,1 2 TO_CART cart12 40,22 -}. Lines that do not read so, or
 * whose cells are off the map, are left out (the robot is then taken over from the device model, as without a
 * handover).
 * <p>
 * Threads: the fleet's thread refreshes what this instance shares ({@link #share}), takes what it inherits
 * ({@link #take}) and ends its hold ({@link #holdEnded}); the beat thread reads what is shared ({@link #shared});
 * the bus's thread records what the leader shared ({@link #heard}). Volatile fields, but for the hold's (the fleet's
 * thread's).
 */
final class ErrandHandover {

    /** The most robots read from one handover (a fleet far larger than robot-sim's largest map). */
    static final int MAX_ROBOTS = 20_000;
    private static final String NONE = "-";
    private static final Pattern ID = Pattern.compile("[A-Za-z0-9_.:-]{1,64}");
    private static final Pattern CELL = Pattern.compile("(\\d{1,6}),(\\d{1,6})");

    /** What a takeover continues: each robot's errand, dock and the carts it was given. */
    record Table(Map<String, Errands.Errand> errands, Map<String, Cell> docks, Map<String, Integer> given) {
        static final Table EMPTY = new Table(Map.of(), Map.of(), Map.of());

        /**
         * @param adopted the robots taken over already
         * @return whether a robot not taken over yet went for the cart (it keeps it: its node died, and the node that
         *         polls it next takes it over on its errand)
         */
        boolean holds(String cart, Set<String> adopted) {
            return errands.values().stream().anyMatch(e -> e.leg() == Errands.Leg.TO_CART && cart.equals(e.cart())
                    && !adopted.contains(e.robot()));
        }

        /** @return the storage cells given to robots not taken over yet that carry carts there */
        Set<Cell> heldDrops(Set<String> adopted) {
            Set<Cell> held = new HashSet<>();
            errands.values().stream().filter(e -> e.leg() == Errands.Leg.TO_STORAGE && e.drop() != null
                    && !adopted.contains(e.robot())).forEach(e -> held.add(e.drop()));
            return held;
        }
    }

    /** Wall time between two refreshes of what this instance shares: a beat's. */
    private static final long SHARE_NANOS = FleetLeadership.BEAT_MILLIS * 1_000_000L;

    /** What this instance shares while it drives the fleet; empty until it does. */
    private volatile String shared = "";
    private volatile long sharedAtNanos;
    /** What the instance that drives the fleet shared last, while this one stands by, until taken. */
    private volatile String heard;
    /**
     * Wall time for which the robots of a handover not taken over yet keep their carts and storage cells: their new
     * owner polls them once the dead node's lease expired (2 s), about when this instance took the fleet over.
     */
    static final long HOLD_NANOS = 10_000_000_000L;
    /** When the last handover was taken, while its hold runs; the fleet's thread only. */
    private long holdFromNanos;
    private boolean holding;

    /** The fleet's thread, at each look while it drives the fleet: the table is read again once per beat. */
    void share(Supplier<String> table) {
        long now = System.nanoTime();
        if (shared.isEmpty() || now - sharedAtNanos >= SHARE_NANOS) {
            shared = table.get();
            sharedAtNanos = now;
        }
    }

    /** @return what this instance shares: its errand table, at most a beat old; empty until it drives the fleet */
    String shared() {
        return shared;
    }

    /** This instance stops driving the fleet: it shares nothing until it drives it again. */
    void standBy() {
        shared = "";
    }

    /** The instance that drives the fleet shared its table (heard while this one stands by: the last is kept). */
    void heard(String text) {
        heard = text;
    }

    /** @return the table heard since the last call, or null: what this instance continues once it drives the fleet */
    Table take(Grid grid) {
        String text = heard;
        if (text == null) {
            return null;
        }
        heard = null;
        holding = true;
        holdFromNanos = System.nanoTime();
        return read(text, grid);
    }

    /** @return true once, when the hold of the handover taken last ended ({@link #HOLD_NANOS}) */
    boolean holdEnded(long nowNanos) {
        if (!holding || nowNanos - holdFromNanos < HOLD_NANOS) {
            return false;
        }
        holding = false;
        return true;
    }

    /**
     * @param errands the errands of the robots that have one
     * @param docks   every robot's dock known
     * @param given   the carts each robot was given
     * @return the handover's text
     */
    static String write(Collection<Errands.Errand> errands, Map<String, Cell> docks, Map<String, Integer> given) {
        Map<String, Errands.Errand> byRobot = new HashMap<>();
        errands.forEach(e -> byRobot.put(e.robot(), e));
        StringBuilder text = new StringBuilder(docks.size() * 40);
        Set<String> robots = new TreeSet<>(docks.keySet());
        robots.addAll(byRobot.keySet());
        for (String robot : robots) {
            Errands.Errand e = byRobot.get(robot);
            text.append(robot).append(' ').append(cell(docks.get(robot))).append(' ')
                    .append(given.getOrDefault(robot, 0)).append(' ')
                    .append(e == null ? Errands.Leg.NONE : e.leg()).append(' ')
                    .append(e == null || e.cart() == null ? NONE : e.cart()).append(' ')
                    .append(cell(e == null ? null : e.cartCell())).append(' ')
                    .append(cell(e == null ? null : e.drop())).append('\n');
        }
        return text.toString();
    }

    /**
     * @param text a handover's text (from another node: read with care)
     * @param grid the map its cells must lie on
     * @return the robots' errands (those with one), docks and given carts; lines that do not read are left out
     */
    static Table read(String text, Grid grid) {
        if (text == null || text.isEmpty()) {
            return Table.EMPTY;
        }
        Map<String, Errands.Errand> errands = new HashMap<>();
        Map<String, Cell> docks = new HashMap<>();
        Map<String, Integer> given = new HashMap<>();
        int robots = 0;
        for (String line : text.split("\n")) {
            String[] f = line.split(" ");
            if (++robots > MAX_ROBOTS || f.length != 7 || !ID.matcher(f[0]).matches()
                    || !f[2].matches("\\d{1,6}")) {
                continue;
            }
            Errands.Leg leg = leg(f[3]);
            String cart = NONE.equals(f[4]) ? null : f[4];
            Cell dock = cell(f[1], grid);
            Cell cartCell = cell(f[5], grid);
            Cell drop = cell(f[6], grid);
            if (leg == null || cart != null && !ID.matcher(cart).matches() || dock == null && !NONE.equals(f[1])
                    || cartCell == null && !NONE.equals(f[5]) || drop == null && !NONE.equals(f[6])) {
                continue;
            }
            String robot = f[0];
            if (dock != null && grid.area(dock) == Grid.DOCKING) {
                docks.put(robot, dock);
            }
            given.put(robot, Integer.parseInt(f[2]));
            if (leg != Errands.Leg.NONE) {
                errands.put(robot, new Errands.Errand(robot, leg, cart, cartCell, drop, dock));
            }
        }
        return new Table(Map.copyOf(errands), Map.copyOf(docks), Map.copyOf(given));
    }

    private static Errands.Leg leg(String name) {
        for (Errands.Leg leg : Errands.Leg.values()) {
            if (leg.name().equals(name)) {
                return leg;
            }
        }
        return null;
    }

    private static String cell(Cell c) {
        return c == null ? NONE : c.x() + "," + c.y();
    }

    /** @return the cell, or null for {@code -}, text that is not a cell, or a cell off the map */
    private static Cell cell(String text, Grid grid) {
        var m = CELL.matcher(text);
        if (!m.matches()) {
            return null;
        }
        Cell c = new Cell(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)));
        return grid.inside(c) ? c : null;
    }
}
