package eu.brain.iot.benchmarks.robotsim;

import eu.brain.iot.robotsim.cli.CliErrors;
import eu.brain.iot.robotsim.cli.UsageException;
import eu.brain.iot.robotsim.cli.Values;
import eu.brain.iot.robotsim.view.ViewPublisher;
import eu.brain.iot.robotsim.world.CommandRejectedException;
import eu.brain.iot.robotsim.world.Commands;
import eu.brain.iot.robotsim.world.MapGenerator;
import eu.brain.iot.robotsim.world.Robot;
import eu.brain.iot.robotsim.world.SimRules;
import eu.brain.iot.robotsim.world.StepEngine;
import eu.brain.iot.robotsim.world.Terrain;
import eu.brain.iot.robotsim.world.WarehouseMap;
import eu.brain.iot.robotsim.world.World;
import java.io.PrintStream;
import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * Times the world thread's work per step on a generated warehouse: the step itself (missions, path planning,
 * sensors, moves, counters) plus publishing the changed robots' JSON. Every idle robot gets a new random errand
 * (go somewhere, pick or place) each step, so all robots keep working.
 */
@Command(name = "step-bench", sortOptions = false, usageHelpWidth = 120,
        customSynopsis = "java -cp benchmarks/target/benchmarks.jar eu.brain.iot.benchmarks.robotsim.StepBench "
                + "[options]")
public final class StepBench implements Callable<Integer> {
    @Spec
    private CommandSpec spec;
    private final PrintStream out;
    private int robots = 1000;
    private int carts = 2000;
    private int width = 200;
    private int height = 100;
    private int steps = 600;
    private int warmup = 200;
    private long seed = 1;

    @Option(names = {"--help", "-h"}, usageHelp = true, order = 8, description = "show this help")
    private boolean help;

    private StepBench(PrintStream out) {
        this.out = out;
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /** Returns the exit code: 0 measured, 2 bad command line. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CliErrors.install(new CommandLine(new StepBench(out)), "step-bench", false, out, err).execute(args);
    }

    @Option(names = "--robots", paramLabel = "N", order = 1, description = "robots (default 1000)")
    void robots(String v) {
        robots = Values.wholeInt(spec, "--robots", v, 1, 1_000_000);
    }

    @Option(names = "--carts", paramLabel = "N", order = 2, description = "carts (default 2000)")
    void carts(String v) {
        carts = Values.wholeInt(spec, "--carts", v, 0, 1_000_000);
    }

    @Option(names = "--width", paramLabel = "N", order = 3, description = "map width (default 200)")
    void width(String v) {
        width = Values.wholeInt(spec, "--width", v, 7, 5000);
    }

    @Option(names = "--height", paramLabel = "N", order = 4, description = "map height (default 100)")
    void height(String v) {
        height = Values.wholeInt(spec, "--height", v, 12, 5000);
    }

    @Option(names = "--steps", paramLabel = "N", order = 5, description = "measured steps (default 600)")
    void steps(String v) {
        steps = Values.wholeInt(spec, "--steps", v, 1, 1_000_000);
    }

    @Option(names = "--warmup", paramLabel = "N", order = 6, description = "steps before measuring (default 200)")
    void warmup(String v) {
        warmup = Values.wholeInt(spec, "--warmup", v, 0, 1_000_000);
    }

    @Option(names = "--seed", paramLabel = "N", order = 7, description = "seed of the map and the errands (default 1)")
    void seed(String v) {
        seed = Values.whole(spec, "--seed", v, Long.MIN_VALUE, Long.MAX_VALUE);
    }

    @Override
    public Integer call() throws UsageException {
        WarehouseMap map;
        try {
            map = MapGenerator.generate(width, height, robots, carts, Math.max(1, width / 40), seed);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        World world = new World(map, SimRules.DEFAULT.withSeed(seed).withDoorOpenSteps(0));
        StepEngine engine = new StepEngine(world, i -> false);
        Commands commands = new Commands(world);
        ViewPublisher views = new ViewPublisher(world);
        for (int d = 0; d < world.doorCount(); d++) {
            commands.door(d, true);
        }
        Random random = new Random(seed);
        out.printf("step-bench: %s, %d robots, %d carts; %d warm-up steps, %d measured%n",
                map.name(), robots, carts, warmup, steps);
        long first = timeStep(world, engine, commands, views, random);
        for (int i = 1; i < warmup; i++) {
            timeStep(world, engine, commands, views, random);
        }
        long[] nanos = new long[steps];
        for (int i = 0; i < steps; i++) {
            nanos[i] = timeStep(world, engine, commands, views, random);
        }
        Arrays.sort(nanos);
        double mean = Arrays.stream(nanos).average().orElse(0) / 1e6;
        out.printf("step time: mean %.2f ms, p50 %.2f ms, p99 %.2f ms, max %.2f ms (first step, all robots "
                        + "planning: %.2f ms); budget 500 ms per step%n", mean, nanos[steps / 2] / 1e6,
                nanos[(int) Math.min(steps - 1, Math.ceil(steps * 0.99) - 1)] / 1e6, nanos[steps - 1] / 1e6,
                first / 1e6);
        long worstReplan = 0;
        for (int round = 0; round < REPLAN_ROUNDS; round++) {
            worstReplan = Math.max(worstReplan, timeReplanStep(world, engine, commands, views, random));
        }
        out.printf("step in which every robot plans a new path at once (warm, worst of %d): %.2f ms%n",
                REPLAN_ROUNDS, worstReplan / 1e6);
        out.printf("after %d steps: near misses %d, deadlocks %d%n", world.step(), world.nearMisses(),
                world.deadlocks());
        out.flush();
        return 0;
    }

    private static final int REPLAN_ROUNDS = 5;

    /** Cancels every robot's missions, gives each a new random goal, and times the step that plans them all. */
    private static long timeReplanStep(World world, StepEngine engine, Commands commands, ViewPublisher views,
                                       Random random) {
        WarehouseMap map = world.map();
        for (int i = 0; i < world.robotCount(); i++) {
            try {
                for (eu.brain.iot.robotsim.world.MissionType type
                        : eu.brain.iot.robotsim.world.MissionType.values()) {
                    while (!commands.cancel(i, type, null).isEmpty()) {
                        // cancel the running one and every queued one
                    }
                }
                int x;
                int y;
                do {
                    x = random.nextInt(map.width());
                    y = random.nextInt(map.height());
                } while (!map.terrain(x, y).passable());
                commands.goTo(i, x, y);
            } catch (CommandRejectedException e) {
                throw new IllegalStateException(e);
            }
        }
        long t0 = System.nanoTime();
        engine.step();
        views.publishAll(world);
        return System.nanoTime() - t0;
    }

    private static long timeStep(World world, StepEngine engine, Commands commands, ViewPublisher views,
                                 Random random) {
        giveErrands(world, commands, random);
        long t0 = System.nanoTime();
        engine.step();
        views.publishAll(world);
        return System.nanoTime() - t0;
    }

    /** Idle robots get an errand: pick when on a cart, place when carrying in storage, else go somewhere. */
    private static void giveErrands(World world, Commands commands, Random random) {
        WarehouseMap map = world.map();
        for (int i = 0; i < world.robotCount(); i++) {
            Robot r = world.robot(i);
            if (r.current() != null || !r.queued().isEmpty()) {
                continue;
            }
            Terrain here = map.terrain(r.x(), r.y());
            try { // the bench's Commands have no queue bound and goals are never walls: nothing is refused
                if (r.carried() < 0 && world.cartAt(r.x(), r.y()) >= 0) {
                    commands.pick(i);
                } else if (r.carried() >= 0 && here == Terrain.STORAGE) {
                    commands.place(i);
                } else {
                    Terrain wanted = r.carried() >= 0 ? Terrain.STORAGE : Terrain.UNLOAD;
                    int x;
                    int y;
                    do {
                        x = random.nextInt(map.width());
                        y = random.nextInt(map.height());
                    } while (map.terrain(x, y) != wanted);
                    commands.goTo(i, x, y);
                }
            } catch (CommandRejectedException e) {
                throw new IllegalStateException(e);
            }
        }
    }
}
