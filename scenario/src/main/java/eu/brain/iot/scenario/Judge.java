package eu.brain.iot.scenario;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.stream.Collectors;

/**
 * Judges a run on robot-sim's ground truth (its {@code /world} document and counters at the end), never on what the
 * behaviours believe:
 * <ul>
 *   <li>REQ-1: every cart was lifted and carried to storage (stands, not carried, on a storage cell);</li>
 *   <li>REQ-2: no single wait of a robot behind another lasted longer than the limit; no cycle of robots waiting on
 *       each other lasted that long (robot-sim's deadlock counter, with its threshold set to the limit); every
 *       errand's destination was reached: every robot is back in the docking area, idle, carrying nothing;</li>
 *   <li>commands: every command the fleet received was accepted, or its refusal was handled (the run completed in
 *       spite of it);</li>
 *   <li>one node at a time per robot: no robot commanded by two nodes within a lease period of wall time (a
 *       robot handed over by a node that died is commanded by its new owner only after the lease expired); a run
 *       on one node has one commander;</li>
 *   <li>the run ended before its deadline.</li>
 * </ul>
 * Public: the multi-node tests in containers ({@code itests-containers}) judge their runs with it. Stateless.
 */
public final class Judge {
    /** The lease period of a robot's ownership in a fabric of nodes, in wall time, unless told otherwise. */
    public static final long DEFAULT_LEASE_MS = 2_000;
    /** Hand-overs named in a failed check; the others are counted. */
    private static final int SHOWN = 10;

    private Judge() {
    }

    /** How a run ended. */
    public enum RunEnd {
        /** the warehouse was done */
        FINISHED,
        /** the deadline ended it */
        DEADLINE,
        /** the node's process ended before the warehouse was done: the run cannot have finished */
        NODE_ENDED
    }

    /**
     * A run that ended by itself ({@code deadlineHitMs} -1) or at the deadline, judged with the default lease period
     * ({@value #DEFAULT_LEASE_MS} ms).
     */
    static Verdict judge(WorldSnapshot end, long waitLimitMs, long deadlineHitMs) {
        return deadlineHitMs >= 0 ? judge(end, waitLimitMs, RunEnd.DEADLINE, deadlineHitMs)
                : judge(end, waitLimitMs, RunEnd.FINISHED, -1);
    }

    /** {@link #judge(WorldSnapshot, long, RunEnd, long, long)} with the default lease period. */
    static Verdict judge(WorldSnapshot end, long waitLimitMs, RunEnd how, long endedMs) {
        return judge(end, waitLimitMs, how, endedMs, DEFAULT_LEASE_MS);
    }

    /**
     * @param end         the world when the run ended
     * @param waitLimitMs the longest a robot may wait behind another (warehouse ms)
     * @param how         how the run ended
     * @param endedMs     the warehouse time (since the scenario's start) at which it ended, for {@code DEADLINE} and
     *                    {@code NODE_ENDED}
     * @param leaseMs     the lease period (wall ms): two nodes commanding one robot closer than this fail the run
     */
    public static Verdict judge(WorldSnapshot end, long waitLimitMs, RunEnd how, long endedMs, long leaseMs) {
        List<Verdict.Check> checks = new ArrayList<>();
        List<String> missing = end.cartsNotInStorage();
        checks.add(new Verdict.Check("REQ-1 every cart lifted and carried to storage", missing.isEmpty(),
                end.cartsInStorage() + "/" + end.cartCount() + " carts in storage"
                        + (missing.isEmpty() ? "" : "; not delivered: " + String.join(", ", missing))));

        List<String> over = end.waitsOver(waitLimitMs);
        checks.add(new Verdict.Check("REQ-2 no wait behind another robot longer than "
                + WarehouseTime.format(waitLimitMs), over.isEmpty(),
                over.isEmpty() ? "longest wait " + WarehouseTime.format(end.longestWaitMs()) + ", "
                        + end.nearMisses() + " robot-in-front detections, " + end.waitsEnded() + " waits ended"
                        : String.join(", ", over)));

        checks.add(new Verdict.Check("REQ-2 no robots blocking each other in a cycle for "
                + WarehouseTime.format(waitLimitMs), end.deadlocks() == 0,
                end.deadlocks() + " deadlocks (robot-sim's counter, threshold = the wait limit)"));

        List<String> away = end.robotsNotHome();
        checks.add(new Verdict.Check("REQ-2 every errand's destination reached, every robot back in docking",
                away.isEmpty(), away.isEmpty() ? end.robotCount() + "/" + end.robotCount() + " robots docked and idle"
                        : "not back: " + String.join("; ", away)));

        checks.add(commands(end, missing.isEmpty() && away.isEmpty()));
        checks.add(oneCommanderAtATime(end, leaseMs));

        checks.add(new Verdict.Check("finished before the deadline", how == RunEnd.FINISHED, switch (how) {
            case FINISHED -> "finished";
            case DEADLINE -> "the deadline ended the run at " + WarehouseTime.format(endedMs) + " of warehouse time";
            case NODE_ENDED -> "the node ended during the run, at " + WarehouseTime.format(endedMs)
                    + " of warehouse time: the run could not finish";
        }));
        return new Verdict(List.copyOf(checks));
    }

    private static Verdict.Check commands(WorldSnapshot end, boolean completed) {
        long accepted = end.commandsAccepted();
        long refused = end.commandsRefused();
        Map<String, Long> by = end.refusedByStatus();
        long failed = end.missionsFailed();
        String counts = accepted + " accepted, " + refused + " refused"
                + (by.isEmpty() ? "" : " (by HTTP status: " + by.entrySet().stream()
                        .map(e -> e.getKey() + " x" + e.getValue()).collect(Collectors.joining(", ")) + ")")
                + (failed == 0 ? "" : ", " + failed + " missions failed when they started");
        String name = "every command accepted or its refusal handled";
        if (accepted + refused == 0) {
            return new Verdict.Check(name, completed, completed ? "no command was needed"
                    : "no command reached the fleet: nothing drove the robots");
        }
        if (refused == 0 && failed == 0) {
            return new Verdict.Check(name, true, counts);
        }
        return new Verdict.Check(name, completed, counts + (completed ? "; the run completed in spite of them"
                : "; the run did not complete: refusals may not have been handled"));
    }

    /**
     * No robot commanded by two nodes within the lease period: each hand-over's two commands (the old node's last,
     * the new node's first) at least {@code leaseMs} of wall time apart.
     */
    static Verdict.Check oneCommanderAtATime(WorldSnapshot end, long leaseMs) {
        String name = "one node commanding each robot at a time (hand-overs at least " + WarehouseTime.format(leaseMs)
                + " of wall time apart)";
        Map<String, String> last = end.lastCommanders();
        if (last.isEmpty()) {
            return new Verdict.Check(name, true, "no robot took a command");
        }
        List<WorldSnapshot.Handover> handovers = end.handovers();
        List<WorldSnapshot.Handover> tooClose = handovers.stream().filter(h -> h.gapWallMillis() < leaseMs).toList();
        if (!tooClose.isEmpty()) {
            String shown = tooClose.stream().limit(SHOWN).map(Judge::describe).collect(Collectors.joining("; "));
            return new Verdict.Check(name, false, tooClose.size() + " robot command(s) from a second node within the "
                    + "lease: " + shown + (tooClose.size() > SHOWN ? "; and " + (tooClose.size() - SHOWN) + " more"
                    : ""));
        }
        TreeSet<String> nodes = new TreeSet<>(last.values());
        handovers.forEach(h -> {
            nodes.add(h.from());
            nodes.add(h.to());
        });
        if (handovers.isEmpty()) {
            return new Verdict.Check(name, true, nodes.size() == 1
                    ? last.size() + " robot(s), all commanded by node " + nodes.first()
                    : last.size() + " robot(s), each commanded by one node only (nodes " + String.join(", ", nodes)
                            + ")");
        }
        long closest = handovers.stream().mapToLong(WorldSnapshot.Handover::gapWallMillis).min().orElse(0);
        return new Verdict.Check(name, true, last.size() + " robot(s) commanded by " + String.join(", ", nodes) + "; "
                + end.handoverCount() + " hand-over(s), the closest " + WarehouseTime.format(closest)
                + " of wall time apart");
    }

    private static String describe(WorldSnapshot.Handover h) {
        return h.robot() + " by " + h.from() + " at " + WarehouseTime.format(h.fromWarehouseMs()) + " then by "
                + h.to() + " at " + WarehouseTime.format(h.warehouseMs()) + " of warehouse time ("
                + Instant.ofEpochMilli(h.fromWallMillis()) + " and " + Instant.ofEpochMilli(h.wallMillis())
                + ", " + WarehouseTime.format(h.gapWallMillis()) + " of wall time apart)";
    }
}
