package eu.brain.iot.benchmarks.driver.install;

import java.io.File;
import java.io.OutputStream;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.util.tracker.ServiceTracker;

import aQute.bnd.osgi.repository.XMLResourceGenerator;
import aQute.bnd.osgi.resource.ResourceBuilder;
import eu.brain.iot.benchmarks.behaviour.event.InstallBenchEvent;
import eu.brain.iot.benchmarks.spi.InstallDriver;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.bms.monitoring.api.ManagerCounters;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * The install benchmark's driver inside the framework: configures the real BIS (Config Admin) with the index, publishes
 * the probe's events on the real bus, uninstalls the probe behaviour between installs.
 * <p>
 * Threads: the launcher's thread calls {@code configure}, {@code uninstall} and {@code counters}; the launcher's
 * publisher threads call {@code publish}, which only reads {@code eventBus} (set by {@code configure} before any
 * publisher starts). The trackers are thread-safe.
 */
public final class InstallDriverActivator implements BundleActivator {

    private static final long WAIT_MS = 60_000;

    private ServiceTracker<EventBus, EventBus> bus;
    private ServiceTracker<ConfigurationAdmin, ConfigurationAdmin> configAdmin;
    private ServiceTracker<BundleInstaller, BundleInstaller> installer;
    private ServiceTracker<BehaviourManagerStatistics, BehaviourManagerStatistics> bms;
    private ServiceTracker<EventBusStatistics, EventBusStatistics> busStatistics;

    @Override
    public void start(BundleContext context) {
        bus = open(context, EventBus.class);
        configAdmin = open(context, ConfigurationAdmin.class);
        installer = open(context, BundleInstaller.class);
        bms = open(context, BehaviourManagerStatistics.class);
        busStatistics = open(context, EventBusStatistics.class);
        context.registerService(InstallDriver.class, new Driver(context), new Hashtable<>());
    }

    private static <T> ServiceTracker<T, T> open(BundleContext context, Class<T> type) {
        ServiceTracker<T, T> tracker = new ServiceTracker<>(context, type, null);
        tracker.open();
        return tracker;
    }

    @Override
    public void stop(BundleContext context) {
        bus.close();
        configAdmin.close();
        installer.close();
        bms.close();
        busStatistics.close();
    }

    private final class Driver implements InstallDriver {
        private final BundleContext context;
        private EventBus eventBus;

        Driver(BundleContext context) {
            this.context = context;
        }

        @Override
        public void configure(String bundleFile, String indexUrl, String journalDir) throws Exception {
            File jar = new File(bundleFile);
            ResourceBuilder resource = new ResourceBuilder();
            resource.addFile(jar, jar.toURI());
            Path index = jar.toPath().resolveSibling("index.xml");
            try (OutputStream out = Files.newOutputStream(index)) {
                new XMLResourceGenerator().resource(resource.build()).name("install benchmark")
                        .base(index.getParent().toUri()).save(out);
            }
            Configuration bis = configAdmin.waitForService(WAIT_MS).getConfiguration("eu.brain.iot.bis", "?");
            Hashtable<String, Object> props = new Hashtable<>();
            props.put("repositories", new String[] { indexUrl });
            props.put("journal.dir", journalDir);
            bis.update(props);
            eventBus = bus.waitForService(WAIT_MS);
            BundleInstaller bi = installer.waitForService(WAIT_MS);
            if (bms.waitForService(WAIT_MS) == null || bi == null) {
                throw new IllegalStateException("the BMS or the BIS did not come up within " + WAIT_MS + " ms");
            }
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
            while (bi.find(List.of(InstallBenchEvent.class.getName())).getValue().isEmpty()) {
                if (System.nanoTime() > deadline) {
                    throw new IllegalStateException("the index " + indexUrl + " offers no probe behaviour");
                }
                Thread.sleep(20); // polling the index's first read at startup, not a measured step
            }
        }

        @Override
        public void publish(String publisher, int seq) {
            InstallBenchEvent event = new InstallBenchEvent();
            event.publisher = publisher;
            event.seq = seq;
            event.sentNanos = System.nanoTime();
            eventBus.deliver(event);
        }

        @Override
        public void uninstall() throws Exception {
            installer.getService().uninstall(BEHAVIOUR, "install benchmark: next round", false).getValue();
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
            while (busStatistics.getService().consumers().stream().anyMatch(c -> BEHAVIOUR.equals(c.bundle))) {
                if (System.nanoTime() > deadline) {
                    throw new IllegalStateException("the probe behaviour is still registered with the bus");
                }
                Thread.sleep(1);
            }
        }

        @Override
        public String counters() {
            ManagerCounters c = bms.getService().counters();
            return "BMS: installs " + c.installs + ", install failures " + c.installFailures + ", events held "
                    + c.heldEvents + ", searches " + c.searches;
        }
    }
}
