package eu.brain.iot.benchmarks;

import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;

import com.sun.net.httpserver.HttpServer;

import eu.brain.iot.benchmarks.spi.InstallDriver;
import eu.brain.iot.benchmarks.spi.InstallProbe;

/**
 * The install-on-demand benchmark: how long from the first event of a type no behaviour consumes to that event inside the
 * {@code notify()} of the behaviour the BMS had the BIS install (the real bus, BMS, BIS and Felix resolver in an
 * embedded Felix; the behaviour from a real R5 index on a file, then served over HTTP on loopback); the behaviour is
 * uninstalled between installs. Then a burst: 4 publishers × N/4 events published while the install runs, all
 * through the bus's hold and hand-over: events/s from the first publish to the last event's arrival, and a check
 * that every publisher's events came once and in order.
 * <p>
 * {@code java -jar benchmarks/target/benchmarks.jar}'s sibling: {@code java -cp benchmarks/target/benchmarks.jar
 * eu.brain.iot.benchmarks.InstallBenchmark [--installs 60] [--warmup 30] [--burst 10000]}.
 */
public final class InstallBenchmark {

    private static final List<String> BUNDLES = List.of("org.osgi.util.function.jar", "org.osgi.util.promise.jar",
            "org.osgi.util.converter.jar", "org.apache.felix.log.jar", "org.osgi.service.component.jar",
            "org.apache.felix.scr.jar", "org.apache.felix.configadmin.jar", "eventbus.jar", "slf4j-api.jar",
            "slf4j-simple.jar",
            "biz.aQute.bnd.util.jar", "biz.aQute.bndlib.jar", "org.osgi.service.repository.jar",
            "org.apache.felix.resolver.jar", "bis-api.jar", "bis-impl.jar", "bms-api.jar", "bms-impl.jar",
            "benchmarks-driver-install.jar");
    private static final String PROBE_BUNDLE = "benchmarks-probe-behaviour.jar";

    private InstallBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int installs = intArg(args, "--installs", 60);
        int warmup = intArg(args, "--warmup", 30);
        int burst = intArg(args, "--burst", 10_000);
        Path bundles = Path.of(stringArg(args, "--bundles", "benchmarks/target/bundles"));
        System.out.printf("install benchmark: %d installs (after %d warm-up) per index, burst of %d events; "
                + "%d processors, load average %s%n", installs, warmup, burst,
                Runtime.getRuntime().availableProcessors(), loadAverage());
        for (String mode : List.of("file", "http")) {
            run(mode, bundles, installs, warmup, burst);
        }
    }

    private static void run(String mode, Path bundles, int installs, int warmup, int burst) throws Exception {
        Path work = Files.createTempDirectory("install-benchmark-");
        Path repo = Files.createDirectories(work.resolve("repository"));
        Path jar = Files.copy(bundles.resolve(PROBE_BUNDLE), repo.resolve(PROBE_BUNDLE),
                StandardCopyOption.REPLACE_EXISTING);
        HttpServer server = null;
        String indexUrl = repo.resolve("index.xml").toUri().toString();
        if (mode.equals("http")) {
            server = serve(repo);
            indexUrl = "http://127.0.0.1:" + server.getAddress().getPort() + "/index.xml";
        }
        InstallProbe probe = new InstallProbe();
        try (EmbeddedFelix felix = EmbeddedFelix.start("install", BUNDLES,
                Map.of("org.slf4j.simpleLogger.defaultLogLevel", "warn"), bundles)) {
            felix.systemContext().registerService(InstallProbe.class, probe, null);
            InstallDriver driver = felix.awaitService(InstallDriver.class, 60_000);
            driver.configure(jar.toString(), indexUrl, work.resolve("journal").toString());

            long[] latencies = new long[installs];
            for (int i = -warmup; i < installs; i++) {
                probe.arm(1);
                driver.publish("single", 0);
                await(probe.done(), "the probe behaviour's first event (install " + i + ")");
                if (i >= 0) {
                    latencies[i] = probe.firstLatencyNanos();
                }
                driver.uninstall();
            }
            Arrays.sort(latencies);
            System.out.printf("%-5s index %-40s installs %d: p50 %.1f ms, p99 %.1f ms, min %.1f ms, max %.1f ms%n",
                    mode, indexUrl.startsWith("file") ? "(file)" : indexUrl, installs, ms(percentile(latencies, 50)),
                    ms(percentile(latencies, 99)), ms(latencies[0]), ms(latencies[latencies.length - 1]));

            burst(driver, probe, burst, mode);
            System.out.println("      " + driver.counters());
        } finally {
            if (server != null) {
                server.stop(0);
            }
            try (Stream<Path> files = Files.walk(work)) {
                files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    /** 4 publishers publish while the install runs: events/s through hold and hand-over, order checked. */
    private static void burst(InstallDriver driver, InstallProbe probe, int events, String mode) throws Exception {
        int publishers = 4;
        int each = events / publishers;
        probe.arm((long) each * publishers);
        CountDownLatch go = new CountDownLatch(1);
        AtomicReference<Throwable> failure = new AtomicReference<>();
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < publishers; p++) {
            String name = "publisher-" + p;
            Thread t = new Thread(() -> {
                try {
                    go.await();
                    for (int i = 0; i < each; i++) {
                        driver.publish(name, i);
                    }
                } catch (Throwable e) {
                    failure.set(e);
                }
            }, name);
            t.start();
            threads.add(t);
        }
        long start = System.nanoTime();
        go.countDown();
        for (Thread t : threads) {
            t.join();
        }
        if (failure.get() != null) {
            throw new BenchmarkException("a publisher failed: " + failure.get());
        }
        await(probe.done(), "the burst's events");
        long elapsed = probe.lastArrivalNanos() - start;
        System.out.printf("%-5s burst: %d events from %d publishers during the install, %,.0f events/s (first publish "
                + "to last arrival, %.1f ms, install included); out of order or duplicated: %d%n", mode,
                probe.received(), publishers, probe.received() / (elapsed / 1e9), ms(elapsed), probe.outOfOrder());
        driver.uninstall();
    }

    private static HttpServer serve(Path dir) throws IOException {
        HttpServer server = HttpServer.create(new InetSocketAddress("127.0.0.1", 0), 0);
        server.createContext("/", exchange -> {
            Path file = dir.resolve(exchange.getRequestURI().getPath().substring(1)).normalize();
            if (!file.startsWith(dir) || !Files.isRegularFile(file)) {
                exchange.sendResponseHeaders(404, -1);
                exchange.close();
                return;
            }
            byte[] body = Files.readAllBytes(file);
            exchange.sendResponseHeaders(200, body.length);
            try (OutputStream out = exchange.getResponseBody()) {
                out.write(body);
            }
        });
        server.start();
        return server;
    }

    private static void await(CountDownLatch latch, String what) throws InterruptedException {
        if (!latch.await(60, TimeUnit.SECONDS)) {
            throw new BenchmarkException(what + " did not arrive within 60 s");
        }
    }

    private static long percentile(long[] sorted, int p) {
        int index = (int) Math.ceil(p / 100.0 * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, index))];
    }

    private static double ms(long nanos) {
        return nanos / 1e6;
    }

    private static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).trim();
        } catch (IOException e) {
            return "unknown";
        }
    }

    private static int intArg(String[] args, String name, int fallback) {
        return Integer.parseInt(stringArg(args, name, String.valueOf(fallback)));
    }

    private static String stringArg(String[] args, String name, String fallback) {
        for (int i = 0; i + 1 < args.length; i++) {
            if (args[i].equals(name)) {
                return args[i + 1];
            }
        }
        return fallback;
    }
}
