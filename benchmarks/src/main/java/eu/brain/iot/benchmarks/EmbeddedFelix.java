package eu.brain.iot.benchmarks;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleException;
import org.osgi.framework.Constants;
import org.osgi.framework.launch.Framework;
import org.osgi.framework.launch.FrameworkFactory;
import org.osgi.util.tracker.ServiceTracker;

import eu.brain.iot.benchmarks.spi.BusDriver;

/**
 * A Felix framework in this process, holding one contender's bundles, with a fresh storage directory that is
 * deleted on close. Only the benchmark's spi package is shared with the launcher (system packages extra).
 */
final class EmbeddedFelix implements AutoCloseable {

    private static final String SPI_EXPORT = BusDriver.class.getPackageName() + ";version=1.0.0";

    private final Framework framework;
    private final Path storage;
    private final List<Bundle> installed = new ArrayList<>();

    private EmbeddedFelix(Framework framework, Path storage) {
        this.framework = framework;
        this.storage = storage;
    }

    /** Start a framework and install and start the contender's bundles, found in {@code bundleDir}. */
    static EmbeddedFelix start(Contender contender, Path bundleDir) throws IOException, BundleException {
        return start(contender.key(), contender.bundles(), contender.frameworkProperties(), bundleDir);
    }

    /** Start a framework and install and start these bundles (file names in {@code bundleDir}). */
    static EmbeddedFelix start(String key, List<String> bundles, Map<String, String> properties, Path bundleDir)
            throws IOException, BundleException {
        List<Path> files = new ArrayList<>();
        for (String name : bundles) {
            Path file = bundleDir.resolve(name);
            if (!Files.isRegularFile(file)) {
                throw new BenchmarkException(key + ": bundle " + file + " is missing; build first with "
                        + "`mvn -B -q -pl benchmarks -am package -DskipTests`, or pass --bundles DIR");
            }
            files.add(file);
        }
        Path storage = Files.createTempDirectory("bus-benchmark-felix-");
        Map<String, String> config = new HashMap<>(properties);
        config.put(Constants.FRAMEWORK_STORAGE, storage.toString());
        config.put(Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT);
        config.put(Constants.FRAMEWORK_SYSTEMPACKAGES_EXTRA, SPI_EXPORT);
        FrameworkFactory factory = ServiceLoader.load(FrameworkFactory.class).findFirst()
                .orElseThrow(() -> new BenchmarkException("no OSGi FrameworkFactory on the class path (Felix jar "
                        + "missing from target/lib?)"));
        Framework framework = factory.newFramework(config);
        framework.start();
        EmbeddedFelix felix = new EmbeddedFelix(framework, storage);
        try {
            for (Path file : files) {
                felix.installed.add(framework.getBundleContext().installBundle(file.toUri().toString()));
            }
            for (Bundle bundle : felix.installed) {
                if (bundle.getHeaders().get(Constants.FRAGMENT_HOST) == null) {
                    start(key, bundle);
                }
            }
        } catch (BundleException | RuntimeException e) {
            felix.close();
            throw e;
        }
        return felix;
    }

    private static void start(String key, Bundle bundle) throws BundleException {
        try {
            bundle.start();
        } catch (BundleException e) {
            throw new BundleException(key + ": bundle " + bundle.getSymbolicName() + " "
                    + bundle.getVersion() + " (" + bundle.getLocation() + ") does not start: " + e.getMessage(), e);
        }
    }

    /** Wait for the driver bundle to see its bus and register the driver. */
    BusDriver awaitDriver(long timeoutMillis) throws InterruptedException {
        ServiceTracker<BusDriver, BusDriver> tracker = new ServiceTracker<>(framework.getBundleContext(),
                BusDriver.class, null);
        tracker.open();
        BusDriver driver = tracker.waitForService(timeoutMillis);
        if (driver == null) {
            throw new BenchmarkException("no bus driver service within " + timeoutMillis + " ms; bundle states: "
                    + describeBundles());
        }
        return driver;
    }

    /** Wait for a service registered inside the framework (whose interface the system bundle exports). */
    <T> T awaitService(Class<T> type, long timeoutMillis) throws InterruptedException {
        ServiceTracker<T, T> tracker = new ServiceTracker<>(framework.getBundleContext(), type, null);
        tracker.open();
        T service = tracker.waitForService(timeoutMillis);
        if (service == null) {
            throw new BenchmarkException("no " + type.getSimpleName() + " service within " + timeoutMillis
                    + " ms; bundle states: " + describeBundles());
        }
        return service;
    }

    /** The system bundle's context: the launcher registers services the framework's bundles use through it. */
    org.osgi.framework.BundleContext systemContext() {
        return framework.getBundleContext();
    }

    /** @return symbolic name, version and state of every installed bundle */
    String describeBundles() {
        StringBuilder out = new StringBuilder();
        for (Bundle b : installed) {
            out.append(out.isEmpty() ? "" : ", ").append(b.getSymbolicName()).append(' ').append(b.getVersion());
            if (b.getState() != Bundle.ACTIVE) {
                out.append(" [state ").append(b.getState()).append(']');
            }
        }
        return out.toString();
    }

    @Override
    public void close() {
        try {
            framework.stop();
            framework.waitForStop(TimeUnit.SECONDS.toMillis(30));
        } catch (BundleException e) {
            System.err.println("warning: framework did not stop cleanly: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try (Stream<Path> paths = Files.walk(storage)) {
            paths.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            System.err.println("warning: could not delete " + storage + ": " + e.getMessage());
        }
    }
}
