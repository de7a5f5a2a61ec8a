package eu.brain.iot.scenario;

import java.util.Map;
import java.util.TreeMap;

/**
 * The figures of a run computed from two ground-truth snapshots (the scenario's start and its end): warehouse
 * time, throughput, the share of robot time spent waiting on another robot, and how long the waits behind a robot
 * lasted. Stateless.
 */
final class Figures {
    private Figures() {
    }

    /** Warehouse milliseconds between two snapshots. */
    static long elapsedMs(WorldSnapshot start, WorldSnapshot end) {
        return (end.step() - start.step()) * end.stepMillis();
    }

    /** Robot-steps spent waiting behind another robot over robot-steps elapsed (0..1). */
    static double waitShare(WorldSnapshot start, WorldSnapshot end) {
        long robotSteps = (end.step() - start.step()) * end.robotCount();
        return robotSteps <= 0 ? 0 : (double) (end.waitSteps() - start.waitSteps()) / robotSteps;
    }

    /** Carts per hour of warehouse time, given the time until every cart was delivered. */
    static double cartsPerHour(int carts, long deliveredAfterMs) {
        return deliveredAfterMs <= 0 ? 0 : carts * 3_600_000.0 / deliveredAfterMs;
    }

    /** Ended waits during the run: length in steps to how many (the end's minus the start's). */
    static TreeMap<Long, Long> waits(WorldSnapshot start, WorldSnapshot end) {
        TreeMap<Long, Long> during = end.endedWaits();
        for (Map.Entry<Long, Long> e : start.endedWaits().entrySet()) {
            during.merge(e.getKey(), -e.getValue(), Long::sum);
        }
        during.values().removeIf(n -> n <= 0);
        return during;
    }

    /** The q-quantile (0..1, nearest rank) of a histogram of lengths, or 0 when it is empty. */
    static long quantile(TreeMap<Long, Long> histogram, double q) {
        long total = histogram.values().stream().mapToLong(Long::longValue).sum();
        if (total == 0) {
            return 0;
        }
        long rank = Math.max(1, (long) Math.ceil(q * total));
        long seen = 0;
        for (Map.Entry<Long, Long> e : histogram.entrySet()) {
            seen += e.getValue();
            if (seen >= rank) {
                return e.getKey();
            }
        }
        return histogram.lastKey();
    }

    /**
     * The most carts per hour one door lets through under robot-sim's rules (BENCHMARKS.md explains it): every
     * errand crosses the door twice; robots crossing one after the other in the same direction need 2 steps per
     * passage (a robot enters only a cell that was empty at the start of the step); a change of direction needs the
     * doorway and the cell behind it clear, 4 steps; so a door used in batches of {@code batch} passages per
     * direction passes a robot every {@code (2 * (batch - 1) + 4) / batch} steps.
     */
    static double doorBoundCartsPerHour(int doors, int batch, long stepMillis) {
        double stepsPerPassage = (2.0 * (batch - 1) + 4) / batch;
        double passagesPerHour = 3_600_000.0 / (stepsPerPassage * stepMillis);
        return doors * passagesPerHour / 2;
    }
}
