package eu.brain.iot.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
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
 *   <li>the run ended before its deadline.</li>
 * </ul>
 * Stateless.
 */
final class Judge {
    private Judge() {
    }

    /**
     * @param end            the world when the run ended
     * @param waitLimitMs    the longest a robot may wait behind another (warehouse ms)
     * @param deadlineHitMs  the warehouse time (since the scenario's start) at which the deadline ended the run, or
     *                       -1 when the run ended by itself
     */
    static Verdict judge(WorldSnapshot end, long waitLimitMs, long deadlineHitMs) {
        return deadlineHitMs >= 0 ? judge(end, waitLimitMs, RunEnd.DEADLINE, deadlineHitMs)
                : judge(end, waitLimitMs, RunEnd.FINISHED, -1);
    }

    /** How a run ended. */
    enum RunEnd {
        /** the warehouse was done */
        FINISHED,
        /** the deadline ended it */
        DEADLINE,
        /** the node's process ended before the warehouse was done: the run cannot have finished */
        NODE_ENDED
    }

    /**
     * @param how     how the run ended
     * @param endedMs the warehouse time (since the scenario's start) at which it ended, for {@code DEADLINE} and
     *                {@code NODE_ENDED}
     */
    static Verdict judge(WorldSnapshot end, long waitLimitMs, RunEnd how, long endedMs) {
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
}
