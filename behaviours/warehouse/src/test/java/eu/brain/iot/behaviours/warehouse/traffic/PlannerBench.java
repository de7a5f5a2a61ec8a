package eu.brain.iot.behaviours.warehouse.traffic;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

/**
 * The planner alone, on a map in robot-sim's format (robots on their docks, {@code R}): every robot runs errands
 * dock -> a cell of the unload area -> a storage cell -> dock for ever, moving each step to the cell its plan gives
 * (doors taken as open; carts not carried), and every round is checked against robot-sim's rules (no two robots in
 * a cell, none entering a cell occupied at the start of the step). Prints the planning time per step (mean, p50,
 * p99, max), errands per warehouse hour (a step is 0.5 s) and the planner's counters. The errands' cells are drawn
 * with the seed given (1 by default): throughput differs by a few percent from seed to seed, so a change in the
 * planner's behaviour is judged over several seeds. A benchmark, not a test:
 * {@code behaviours/warehouse/planner-bench} runs it.
 */
public final class PlannerBench {
    private PlannerBench() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 1) {
            System.err.println("usage: PlannerBench MAP [steps] [window] [warmup] [robots] [seed]");
            System.exit(2);
        }
        List<String> rows = new ArrayList<>();
        boolean inMap = false;
        for (String line : Files.readAllLines(Path.of(args[0]))) {
            if (inMap && !line.isEmpty()) {
                rows.add(line);
            }
            inMap |= line.trim().equals("map:");
        }
        int steps = args.length > 1 ? Integer.parseInt(args[1]) : 600;
        int window = args.length > 2 ? Integer.parseInt(args[2]) : 16;
        int warmup = args.length > 3 ? Integer.parseInt(args[3]) : 100;
        int limit = args.length > 4 ? Integer.parseInt(args[4]) : Integer.MAX_VALUE;
        long seed = args.length > 5 ? Long.parseLong(args[5]) : 1;
        TrafficMap map = TrafficMap.parse(String.join("\n", rows));
        List<Integer> docks = new ArrayList<>();
        List<Integer> unload = new ArrayList<>();
        List<Integer> storage = new ArrayList<>();
        for (int y = 0; y < rows.size(); y++) {
            for (int x = 0; x < rows.get(y).length(); x++) {
                char c = rows.get(y).charAt(x);
                int cell = map.cell(x, y);
                if (c == 'R' && docks.size() < limit) {
                    docks.add(cell);
                } else if (c == 'u' || c == 'C') {
                    unload.add(cell);
                } else if (c == 's') {
                    storage.add(cell);
                }
            }
        }
        MapCheck.refusal(map, window).ifPresent(why -> System.out.println("map check: " + why));
        int n = docks.size();
        FleetPlanner planner = new FleetPlanner(map, n, window);
        int[] at = new int[n];
        int[] goal = new int[n];
        int[] leg = new int[n];
        Random random = new Random(seed);
        for (int r = 0; r < n; r++) {
            at[r] = docks.get(r);
            goal[r] = unload.get(random.nextInt(unload.size()));
        }
        long[] nanos = new long[steps];
        long errands = 0;
        long violations = 0;
        boolean[] occupied = new boolean[map.cells()];
        for (int s = -warmup; s < steps; s++) {
            for (int r = 0; r < n; r++) {
                if (at[r] == goal[r]) {
                    leg[r] = (leg[r] + 1) % 3;
                    errands += s >= 0 && leg[r] == 0 ? 1 : 0;
                    goal[r] = switch (leg[r]) {
                        case 0 -> unload.get(random.nextInt(unload.size()));
                        case 1 -> storage.get(random.nextInt(storage.size()));
                        default -> docks.get(r);
                    };
                    if (leg[r] == 0) {
                        leg[r] = 0;
                    }
                }
                planner.robot(r, at[r], goal[r], false, false);
            }
            long t0 = System.nanoTime();
            planner.plan();
            long took = System.nanoTime() - t0;
            if (s >= 0) {
                nanos[s] = took;
            }
            Arrays.fill(occupied, false);
            for (int r = 0; r < n; r++) {
                occupied[at[r]] = true;
            }
            int[] next = new int[n];
            for (int r = 0; r < n; r++) {
                next[r] = planner.path(r)[1];
                if (next[r] != at[r] && occupied[next[r]]) {
                    violations++;
                }
            }
            at = next;
        }
        Arrays.sort(nanos);
        double hours = steps * 0.5 / 3600;
        System.out.printf("planner-bench: %s, %dx%d, %d robots, window %d, %d steps measured after %d%n",
                args[0], map.width(), map.height(), n, window, steps, warmup);
        System.out.printf("planning time per step: mean %.2f ms, p50 %.2f ms, p99 %.2f ms, max %.2f ms%n",
                Arrays.stream(nanos).average().orElse(0) / 1e6, nanos[steps / 2] / 1e6,
                nanos[(int) Math.min(steps - 1, Math.ceil(steps * 0.99) - 1)] / 1e6, nanos[steps - 1] / 1e6);
        System.out.printf("errands (dock -> unload -> storage -> dock) per warehouse hour: %.0f; rule violations: %d;"
                + " robots held: %d; nodes expanded per step: %d%n", errands / hours, violations,
                planner.fallbacks(), planner.expansions() / (steps + warmup));
    }
}
