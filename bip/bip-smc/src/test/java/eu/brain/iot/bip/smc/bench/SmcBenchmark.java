package eu.brain.iot.bip.smc.bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.smc.SmcSession;
import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * Times the statistical model checker on the PRISM warehouse benchmark (Warehouse3.bip): load and check, generate
 * and compile, then {@code P=? [ F<=1000 R1.c>=10 ]} with ε = δ = 0.01 (26,492 traces): the first sampling run
 * in this JVM (cold JIT) and the best of the next runs, on the given thread counts; steps/s of the interpreter for
 * comparison; and the φ2-like sweep {@code P=? [ F<=1000 R1.c >= x ] for x = 0:12:1}. Usage (from the repository
 * root, after {@code mvn -pl bip/bip-smc -am test-compile}):
 * <pre>java -cp bip/bip-lang/target/classes:bip/bip-generator/target/classes:bip/bip-smc/target/classes:\
 *   bip/bip-smc/target/test-classes eu.brain.iot.bip.smc.bench.SmcBenchmark [threads...]</pre>
 */
public final class SmcBenchmark {

    private static final Path MODEL = Path.of("bip/bip-smc/src/test/resources/smc/prism-warehouse/Warehouse3.bip");

    private SmcBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        List<Integer> threads = new ArrayList<>();
        for (String a : args) {
            threads.add(Integer.parseInt(a));
        }
        if (threads.isEmpty()) {
            threads = List.of(2, 1);
        }
        System.out.printf(Locale.ROOT, "%d cores, Java %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.version"));
        long t0 = System.nanoTime();
        Diagnostics d = new Diagnostics();
        SmcSession s = SmcSession.load(List.of(MODEL), List.of(), null, d).orElseThrow(() -> new IllegalStateException(
                d.toString()));
        Query q = s.parse("P=? [ F<=1000 R1.c>=10 ]");
        long t1 = System.nanoTime();
        SmcOptions o = SmcOptions.defaults();
        SystemSimulator sim = s.simulator(List.of(q), o, () -> SimulationExterns.NONE, List.of());
        long t2 = System.nanoTime();
        System.out.printf(Locale.ROOT, "load+check %.0f ms, generate+compile %.0f ms%n", (t1 - t0) / 1e6,
                (t2 - t1) / 1e6);
        for (int n : threads) {
            SmcOptions on = o.withThreads(n);
            PointResult first = s.runner(sim, List.of(q), on).point(0, new double[0], null);
            print("first run, " + n + " thread(s)", first, n);
            PointResult best = null;
            for (int i = 0; i < 5; i++) {
                PointResult r = s.runner(sim, List.of(q), on).point(0, new double[0], null);
                best = best == null || r.samplingNanos() < best.samplingNanos() ? r : best;
            }
            print("best of 5 next runs, " + n + " thread(s)", best, n);
        }
        SmcOptions interpreted = o.withEngine(SystemSimulator.Engine.INTERPRETED).withThreads(1).with("epsilon", "0.1");
        SystemSimulator interp = s.simulator(List.of(q), interpreted, () -> SimulationExterns.NONE, List.of());
        PointResult slow = s.runner(interp, List.of(q), interpreted).point(0, new double[0], null);
        print("interpreter (reference), 1 thread, epsilon 0.1", slow, 1);
        Query sweep = s.parse("P=? [ F<=1000 R1.c >= x ] for x = 0:12:1");
        SystemSimulator sweepSim = s.simulator(List.of(sweep), o, () -> SimulationExterns.NONE, List.of());
        int n = threads.get(0);
        long t3 = System.nanoTime();
        List<PointResult> points = s.runner(sweepSim, List.of(sweep), o.withThreads(n)).run(0, null);
        long t4 = System.nanoTime();
        long steps = points.stream().mapToLong(PointResult::steps).sum();
        long traces = points.stream().mapToLong(PointResult::samples).sum();
        System.out.printf(Locale.ROOT, "sweep x = 0:12:1 (13 points, %,d traces, %,d steps), %d thread(s): %.2f s%n",
                traces, steps, n, (t4 - t3) / 1e9);
        StringBuilder values = new StringBuilder("  ");
        for (PointResult r : points) {
            values.append(String.format(Locale.ROOT, "x=%d %.4f  ", (int) r.params()[0], r.estimate()));
        }
        System.out.println(values.toString().stripTrailing());
    }

    private static void print(String what, PointResult r, int threads) {
        double s = r.samplingNanos() / 1e9;
        System.out.printf(Locale.ROOT, "%s: p = %.4f [%.4f, %.4f], %,d traces, %,d steps (%.0f per trace), sampling "
                + "%.3f s, %,.0f traces/s, %,.0f steps/s per core%n", what, r.estimate(), r.lower(), r.upper(),
                r.samples(), r.steps(), (double) r.steps() / r.samples(), s, r.samples() / s,
                r.steps() / s / threads);
    }
}
