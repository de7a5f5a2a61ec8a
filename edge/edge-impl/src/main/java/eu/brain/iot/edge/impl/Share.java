package eu.brain.iot.edge.impl;

import java.util.LinkedHashSet;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A node's share of the fleet, from the configuration's {@code share} and {@code doors.owner}: every device
 * ({@code all}); the K-th of N nodes ({@code K/N}: robot number modulo N equal to K-1, for robots named
 * {@code robotNN}, a stable hash of the id otherwise; every door when K is {@code doors.owner}); or a list of ids.
 * Immutable.
 *
 * @param mode       how devices are shared
 * @param node       K, the node's number in {@code K/N} (1..N), 0 otherwise
 * @param nodes      N, the number of nodes in {@code K/N}, 0 otherwise
 * @param doorsOwner the node number (1..N) that owns the doors under {@code K/N}
 * @param ids        the listed ids under {@link Mode#LIST}, empty otherwise
 * @param leased     the share is this node's only once a lease manager takes it (a node of a fabric with device
 *                   leases first hears who holds what: its share may be held by another node)
 */
record Share(Mode mode, int node, int nodes, int doorsOwner, Set<String> ids, boolean leased) {

    /** How the devices are shared. */
    enum Mode {
        /** Every device: one node drives the whole fleet. */
        ALL,
        /** The K-th of N nodes' part, by robot number. */
        MODULO,
        /** The devices listed. */
        LIST
    }

    /** The value that means every device. */
    static final String ALL = "all";
    static final Share EVERY_DEVICE = new Share(Mode.ALL, 0, 0, 1, Set.of(), false);

    private static final Pattern MODULO_SHARE = Pattern.compile("(\\d{1,6})/(\\d{1,6})");
    private static final Pattern NUMBERED_ROBOT = Pattern.compile("robot0*(\\d{1,9})");
    private static final Pattern ID = Pattern.compile("[A-Za-z0-9_.-]+");

    Share {
        ids = java.util.Collections.unmodifiableSet(new LinkedHashSet<>(ids)); // in the order written
    }

    /**
     * @param share      {@code all} (or empty), {@code K/N}, or device ids separated by commas
     * @param doorsOwner the node (1..N) that owns the doors under {@code K/N}
     * @throws IllegalArgumentException naming the property at fault and what to write
     */
    static Share parse(String share, int doorsOwner) {
        String s = share == null ? "" : share.strip();
        if (s.isEmpty() || s.equalsIgnoreCase(ALL)) {
            return EVERY_DEVICE;
        }
        Matcher m = MODULO_SHARE.matcher(s);
        if (m.matches()) {
            int k = Integer.parseInt(m.group(1));
            int n = Integer.parseInt(m.group(2));
            if (n < 1 || k < 1 || k > n) {
                throw new IllegalArgumentException("share '" + s + "' must be K/N with 1 <= K <= N (this node is "
                        + "the K-th of N), e.g. 2/3");
            }
            if (doorsOwner < 1 || doorsOwner > n) {
                throw new IllegalArgumentException("doors.owner must be a node number from 1 to " + n
                        + " (share " + s + "), found " + doorsOwner);
            }
            return new Share(Mode.MODULO, k, n, doorsOwner, Set.of(), false);
        }
        Set<String> ids = new LinkedHashSet<>();
        for (String part : s.split(",")) {
            String id = part.strip();
            if (!ID.matcher(id).matches()) {
                throw new IllegalArgumentException("share holds '" + id + "': write 'all', K/N (e.g. 2/3) or device"
                        + " ids separated by commas (letters, digits, '_', '.' or '-', e.g. robot1,robot4,door1)");
            }
            ids.add(id);
        }
        return new Share(Mode.LIST, 0, 0, doorsOwner, ids, false);
    }

    /** The same share, owned only once a lease manager takes it when {@code leased}. */
    Share withLeased(boolean leased) {
        return new Share(mode, node, nodes, doorsOwner, ids, leased);
    }

    /** Whether the share holds this device of the fleet. */
    boolean holds(String id, DeviceKind kind) {
        return switch (mode) {
            case ALL -> true;
            case LIST -> ids.contains(id);
            case MODULO -> kind == DeviceKind.DOOR ? node == doorsOwner : Math.floorMod(number(id), nodes) == node - 1;
        };
    }

    /** The robot's number ({@code robot12}: 12); for another name, a hash of it that every node computes alike. */
    static long number(String id) {
        Matcher m = NUMBERED_ROBOT.matcher(id);
        return m.matches() ? Long.parseLong(m.group(1)) : id.hashCode() & 0x7fffffffL;
    }

    @Override
    public String toString() {
        return switch (mode) {
            case ALL -> ALL;
            case MODULO -> node + "/" + nodes + " (doors on node " + doorsOwner + ")";
            case LIST -> String.join(",", ids);
        } + (leased ? ", once leased" : "");
    }
}
