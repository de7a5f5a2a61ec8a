package eu.brain.iot.federation.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.Predicate;

/**
 * Which node owns which device of the fleet, decided by every node from the leases it hears, the same way on every
 * node (the policy; {@link LeaseManager} applies it):
 * <ul>
 * <li>a device belongs to the alive node whose share holds it (the lowest name if several), else to the alive node
 * at {@code floorMod(id.hashCode(), alive)} in name order (this node counting as alive);</li>
 * <li>a node releases at once a device that an alive node of a lower name also owns; a device that belongs to
 * another node it hands over at once when the device is at rest (a robot parked idle and empty, a door closed: the
 * edge's {@code DeviceOwnership.atRest}), the others one at a time, one every half lease period: a device changing
 * hands is commanded by nobody for a lease period and a quarter (next rule), and robots handed back all at once to a
 * node started again would stand still together in each other's way;</li>
 * <li>a node takes a device that belongs to it once no alive node's lease lists it: the holder's lease without the
 * device, or its expiry, comes first, so that no device is commanded by two nodes at once; a device its holder
 * released, or held when its lease lapsed, is taken only a lease period and a quarter after that release or that
 * last lease was heard, so that the holder's last command and the taker's first are more than a lease period apart
 * (a holder renews every quarter of a lease period and commands in between);</li>
 * <li>a node that has just started takes nothing for one lease period: it first hears who holds what (a node killed
 * and started again finds its share held by others); nor while a node alive was first heard less than a lease period
 * ago, as that node may have released a device just before (its release unheard here);</li>
 * <li>a device no node has claimed since this node started (in no share and held by no node it heard, alive or
 * lapsed) is taken only once this node has run for the join grace: the node whose share holds it has that long to
 * join, so that a fabric whose nodes start a few seconds apart does not first hand every device to the node that
 * came first (and its behaviours installed there, away from their devices). A device of a node heard that died is
 * taken at once;</li>
 * <li>a node is alive while its last lease is younger than the lease period.</li>
 * </ul>
 * Time is {@link System#nanoTime()} as passed in. Threads: one owner thread (the lease manager's), no locking.
 */
final class LeaseTable {

    /** A node's lease as heard: its share, what it owns, when it was heard and for how long it holds. */
    record Lease(String node, Set<String> share, Set<String> owned, long heardNanos, long leaseNanos) {
        boolean alive(long now) {
            return now - heardNanos <= leaseNanos;
        }
    }

    /** What this node does now. */
    record Plan(Set<String> take, Set<String> release) {
        boolean empty() {
            return take.isEmpty() && release.isEmpty();
        }
    }

    private final String self;
    private final long leaseNanos;
    private final long startedNanos;
    private final long joinGraceNanos;
    private final Map<String, Lease> heard = new TreeMap<>();
    /** Every device a lease heard since this table started named in its share or as owned. */
    private final Set<String> claimed = new TreeSet<>();
    /** When a holder's lease was first heard without a device its previous lease listed (its release). */
    private final Map<String, Long> releasedNanos = new TreeMap<>();
    /** When each node's first lease was heard by this table. */
    private final Map<String, Long> firstHeardNanos = new TreeMap<>();
    /** When this node last handed over a device that was not at rest. */
    private Long busyHandOverNanos;

    /**
     * @param leaseNanos     how long a lease holds; this node takes nothing for that long after it started
     * @param startedNanos   when this node started (or came back into its fabric)
     * @param joinGraceNanos how long after it started this node leaves a device no node has claimed to the node
     *                       whose share holds it (at least one lease period)
     */
    LeaseTable(String self, long leaseNanos, long startedNanos, long joinGraceNanos) {
        this.self = self;
        this.leaseNanos = leaseNanos;
        this.startedNanos = startedNanos;
        this.joinGraceNanos = Math.max(leaseNanos, joinGraceNanos);
    }

    /** Another node's lease; this node's own is ignored. */
    void heard(Lease lease) {
        if (!lease.node().equals(self)) {
            Lease before = heard.put(lease.node(), lease);
            firstHeardNanos.putIfAbsent(lease.node(), lease.heardNanos());
            if (before != null) {
                for (String d : before.owned()) {
                    if (!lease.owned().contains(d)) {
                        releasedNanos.put(d, lease.heardNanos());
                    }
                }
            }
            claimed.addAll(lease.share());
            claimed.addAll(lease.owned());
        }
    }

    /** @return the other nodes whose lease holds now, by name */
    List<Lease> alive(long now) {
        return heard.values().stream().filter(l -> l.alive(now)).toList();
    }

    /** @return the nodes heard whose lease lapsed, by name */
    List<String> lapsed(long now) {
        return heard.values().stream().filter(l -> !l.alive(now)).map(Lease::node).toList();
    }

    /**
     * @param fleet   every device of the fleet
     * @param share   the devices this node's configuration gives it
     * @param owned   the devices this node owns now
     * @param atRest  whether a device this node owns may change hands without interrupting anything
     */
    Plan plan(long now, Set<String> fleet, Set<String> share, Set<String> owned, Predicate<String> atRest) {
        List<Lease> alive = alive(now);
        Set<String> release = new TreeSet<>();
        Set<String> busy = new TreeSet<>();
        for (String d : owned) {
            boolean lowerHolds = alive.stream().anyMatch(l -> l.node().compareTo(self) < 0 && l.owned().contains(d));
            if (lowerHolds) {
                release.add(d);
            } else if (!self.equals(owner(d, share, alive))) {
                (atRest.test(d) ? release : busy).add(d);
            }
        }
        if (!busy.isEmpty() && (busyHandOverNanos == null || now - busyHandOverNanos >= leaseNanos / 2)) {
            release.add(busy.iterator().next());
            busyHandOverNanos = now;
        }
        Set<String> take = new TreeSet<>();
        if (now - startedNanos > leaseNanos && everyAliveNodeHeardForALease(alive, now)) {
            boolean joinGraceOver = now - startedNanos > joinGraceNanos;
            for (String d : fleet) {
                Long released = releasedNanos.get(d);
                boolean mayTake = (joinGraceOver || share.contains(d) || claimed.contains(d))
                        && (released == null || now - released >= releaseGapNanos());
                if (mayTake && !owned.contains(d) && self.equals(owner(d, share, alive)) && !heldLately(d, now)) {
                    take.add(d);
                }
            }
        }
        return new Plan(take, release);
    }

    /**
     * Whether a lease heard less than {@link #releaseGapNanos()} ago lists the device: an alive holder's, or a lapsed
     * one's whose last command may still be within a lease period (it renews every quarter of one, and commands in
     * between: taken at the lapse, its last command and the taker's first could be closer than a lease period).
     */
    private boolean heldLately(String device, long now) {
        return heard.values().stream().anyMatch(l -> l.owned().contains(device)
                && now - l.heardNanos() < releaseGapNanos());
    }

    /**
     * How long after a release (or a holder's last lease) was heard its device may be taken: a lease period, and a
     * quarter more for the time the release took to arrive and the holder's last command to land (the judge's rule:
     * two nodes command a robot at least a lease period apart).
     */
    private long releaseGapNanos() {
        return leaseNanos + leaseNanos / 4;
    }

    /**
     * Whether every alive node has been heard for a lease period: a node first heard just now may have released a
     * device a moment before (this node then never heard the release), and commanded it until then.
     */
    private boolean everyAliveNodeHeardForALease(List<Lease> alive, long now) {
        return alive.stream().allMatch(l -> now - firstHeardNanos.getOrDefault(l.node(), now) >= leaseNanos);
    }

    /** The node a device belongs to now. */
    String owner(String device, Set<String> share, List<Lease> alive) {
        if (share.contains(device)) {
            String lower = alive.stream().filter(l -> l.share().contains(device)).map(Lease::node)
                    .filter(n -> n.compareTo(self) < 0).findFirst().orElse(null);
            return lower != null ? lower : self;
        }
        String sharer = alive.stream().filter(l -> l.share().contains(device)).map(Lease::node).findFirst()
                .orElse(null);
        if (sharer != null) {
            return sharer;
        }
        List<String> names = new ArrayList<>();
        names.add(self);
        alive.forEach(l -> names.add(l.node()));
        names.sort(null);
        return names.get(Math.floorMod(device.hashCode(), names.size()));
    }
}
