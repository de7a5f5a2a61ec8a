package eu.brain.iot.benchmarks;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.benchmarks.spi.BusDriver;

/**
 * The event bus benchmark (BENCHMARKS.md, "Event bus"): our bus, Felix EventAdmin (default and Timeout=0) and Aries
 * typedevent, each in its own embedded Felix framework in a JVM of its own ({@link ForkedRun}), one after the
 * other. Run it with
 * {@code java -jar benchmarks/target/benchmarks.jar}; see the module's README.
 */
public final class BusBenchmark {

    private static final long DRIVER_TIMEOUT_MILLIS = 20_000;

    private BusBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        if (Settings.wantsHelp(args)) {
            System.out.print(Settings.usage());
            return;
        }
        Settings settings;
        try {
            settings = Settings.parse(args, defaultBundleDir());
        } catch (BenchmarkException e) {
            System.err.println(e.getMessage());
            System.exit(2);
            return;
        }
        if (settings.resultFile() != null) {
            // a forked JVM: one contender, its result to the launching JVM
            ContenderResult result = run(settings.contenders().get(0), settings);
            ForkedRun.write(result, settings.resultFile());
            System.exit(result.error() == null ? 0 : 1);
            return;
        }
        Report report = new Report(System.out);
        report.environment(settings);
        List<ContenderResult> results = new ArrayList<>();
        for (Contender contender : settings.contenders()) {
            results.add(settings.fork() ? ForkedRun.run(contender, args) : run(contender, settings));
        }
        report.table(results);
        report.load("at the end");
        if (results.stream().anyMatch(r -> r.error() != null)) {
            System.exit(1);
        }
    }

    private static ContenderResult run(Contender contender, Settings settings) {
        System.err.printf("== %s%n", contender.label());
        try (EmbeddedFelix felix = EmbeddedFelix.start(contender, settings.bundleDir())) {
            BusDriver driver = felix.awaitDriver(DRIVER_TIMEOUT_MILLIS);
            BusMeasurements measure = new BusMeasurements(driver, settings);
            // Each phase starts on a collected heap, so no phase pays for the garbage of the one before.
            System.gc();
            BusMeasurements.Throughput eight = measure.throughput(8);
            System.err.printf("   8 consumers: %,.0f events/s%n", eight.median());
            System.gc();
            BusMeasurements.Throughput one = measure.throughput(1);
            System.err.printf("   1 consumer:  %,.0f events/s%n", one.median());
            System.gc();
            BusMeasurements.Latency latency = measure.latency(8);
            System.err.printf("   latency (8 consumers): mean %.1f µs, p99 %.1f µs%n", latency.meanMicros(),
                    latency.percentileMicros(99));
            return new ContenderResult(contender, felix.describeBundles(), eight, one, latency, null);
        } catch (Exception e) {
            String message = e.getMessage() == null ? e.toString() : e.getMessage();
            System.err.println("   FAILED: " + message);
            return ContenderResult.failed(contender, message);
        }
    }

    private static Path defaultBundleDir() {
        try {
            Path launcher = Path.of(BusBenchmark.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            return launcher.resolveSibling("bundles");
        } catch (URISyntaxException | SecurityException e) {
            return Path.of("benchmarks", "target", "bundles");
        }
    }
}
