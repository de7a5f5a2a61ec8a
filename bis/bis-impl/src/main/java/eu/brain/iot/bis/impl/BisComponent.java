package eu.brain.iot.bis.impl;

import java.io.File;
import java.io.IOException;
import java.net.URI;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

import org.osgi.annotation.bundle.Capability;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.metatype.annotations.Designate;
import org.osgi.service.resolver.Resolver;
import org.osgi.util.promise.PromiseFactory;
import org.osgi.util.tracker.ServiceTracker;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.impl.install.Installer;
import eu.brain.iot.bis.impl.journal.Journal;
import eu.brain.iot.bis.impl.repo.Repositories;
import eu.brain.iot.bis.impl.repo.TrustedKeys;
import eu.brain.iot.bis.impl.repo.UrlReader;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * The Bundle Installer Service of a node. At activation it reads its journal and its indexes, installs again what the
 * journal lists, and only then registers the {@link BundleInstaller} service and the {@code bis:*} commands, so that
 * whoever waits for the service (the BMS, the node's ready line) sees the journal's behaviours back. A configuration
 * change restarts it (the journal keeps what is installed; installed bundles stay).
 * <p>
 * Threads: the installer's thread ({@code brain-iot-bis}) resolves, installs and starts; {@code brain-iot-bis-download}
 * threads download bundles (a few at once); {@code brain-iot-bis-repos} threads read indexes (one per index);
 * {@code brain-iot-bis-callbacks} runs promise callbacks; {@code brain-iot-bis-start} restores the journal and
 * registers the services. {@link #registrations}, {@link #closed} and {@link #starter} are guarded by
 * {@code this}.
 * <p>
 * A configuration that cannot be used (a trusted key that is no key, a URL that is no URL, a journal line that
 * cannot be read) is logged as one error saying what and where, and the installer does not run: a bad key must never
 * silently turn signature checks off.
 */
// The service is registered from code once the journal is restored, so DS cannot declare it: declare it here, so that
// a resolver (a node's bndrun, a test's) sees that this bundle provides what the BMS requires.
@Capability(namespace = "osgi.service", attribute = "objectClass:List<String>=\"eu.brain.iot.bis.api.BundleInstaller\"",
        uses = BundleInstaller.class)
@Component(configurationPid = BisComponent.PID, configurationPolicy = ConfigurationPolicy.REQUIRE, immediate = true)
@Designate(ocd = BisConfig.class)
public final class BisComponent {

    public static final String PID = "eu.brain.iot.bis";
    /** How often the start's restore looks whether the indexes it waits for offer the journal's behaviours. */
    private static final long RESTORE_POLL_MS = 100;

    private final Logger log;
    /** Null when the configuration is unusable: then nothing runs and the log says why. */
    private final Parts parts;
    private final List<ServiceRegistration<?>> registrations = new ArrayList<>();
    private boolean closed;
    /** Restores the journal, then registers the services; interrupted when the component goes away first. */
    private Thread starter;

    /** What a running installer consists of. */
    private record Parts(Repositories repositories, Installer installer, ScheduledExecutorService scheduler,
            ExecutorService callbacks, ServiceTracker<EventBusStatistics, EventBusStatistics> statistics,
            long shellWaitMillis, AutoCloseable journalLock) {
    }

    @Activate
    public BisComponent(BundleContext context, BisConfig config, @Reference Resolver resolver,
            @Reference(service = LoggerFactory.class) Logger log) {
        this.log = log;
        Parts started = null;
        try {
            started = start(context, config, resolver);
        } catch (IllegalArgumentException | IOException e) {
            // a bad key or URL must not silently turn verification off: the installer does not run at all
            log.error("Bundle Installer NOT started, its configuration ({}) or journal is unusable: {}", PID,
                    e.getMessage());
        }
        this.parts = started;
    }

    private Parts start(BundleContext context, BisConfig config, Resolver resolver) throws IOException {
        TrustedKeys keys = TrustedKeys.of(config.trusted_keys());
        List<URI> urls = repositoryUrls(config.repositories());
        Path journalDir = journalDir(context, config);
        Journal journal = new Journal(journalDir);
        AutoCloseable journalLock = journal.lock(); // another installer on this journal stops this one here
        Journal.State loaded;
        try {
            loaded = journal.load(); // a broken journal stops here, before any thread starts
        } catch (IOException e) {
            release(journalLock);
            throw e;
        }
        UrlReader reader = new UrlReader(Duration.ofMillis(Math.max(100, config.download_timeout_ms())),
                Duration.ofMillis(Math.max(100, config.download_deadline_ms())));
        ScheduledExecutorService scheduler = Executors.newScheduledThreadPool(Math.max(1, urls.size()),
                named("brain-iot-bis-repos"));
        ExecutorService callbacks = Executors.newSingleThreadExecutor(named("brain-iot-bis-callbacks"));
        Repositories repositories = new Repositories(urls, keys, reader, scheduler, config.refresh_ms(),
                config.retry_initial_ms(), config.retry_max_ms(), config.index_max_bytes(), log::warn, log::info);
        ServiceTracker<EventBusStatistics, EventBusStatistics> statistics = new ServiceTracker<>(context,
                EventBusStatistics.class, null);
        statistics.open();
        int downloadThreads = Math.max(1, config.download_threads());
        ThreadPoolExecutor downloader = new ThreadPoolExecutor(downloadThreads, downloadThreads, 30, TimeUnit.SECONDS,
                new LinkedBlockingQueue<>(), named("brain-iot-bis-download"));
        downloader.allowCoreThreadTimeOut(true);
        File data = context.getDataFile("downloads");
        Path downloads = data != null ? data.toPath() : journalDir.resolve("downloads");
        Installer installer = Installer.create(context, resolver, repositories, reader, journal, loaded,
                Arrays.asList(config.prefer()), Math.max(1, config.activation_timeout_ms()), statistics::getService,
                new Installer.Threads(Executors.newSingleThreadExecutor(named("brain-iot-bis")), downloader,
                        new PromiseFactory(callbacks, scheduler)),
                downloads, Math.max(1, config.bundle_max_bytes()), log::error, log::warn, log::info);
        log.info("Bundle Installer: indexes {}, {} trusted keys, journal {}", urls, keys.keys().size(), journalDir);
        if (urls.isEmpty()) {
            log.warn("Bundle Installer: no repositories configured (repositories of {}): nothing can be installed",
                    PID);
        }
        if (!keys.enabled()) {
            log.warn("Bundle Installer: no trusted.keys configured: index signatures are not checked (bundle"
                    + " hashes still are)");
        }
        Parts parts = new Parts(repositories, installer, scheduler, callbacks, statistics,
                Math.max(1, config.shell_wait_ms()), journalLock);
        repositories.onChange(installer::retryPending);
        repositories.start();
        long restoreTimeout = Math.max(0, config.restore_timeout_ms());
        Thread thread = named("brain-iot-bis-start").newThread(() -> restoreThenRegister(context, parts,
                restoreTimeout));
        synchronized (this) {
            starter = thread;
        }
        thread.start();
        return parts;
    }

    /**
     * Waits until every index was tried once (read, refused or unreachable: an index that was refused will not offer
     * the journal's behaviours by waiting longer), restores the journal, then offers the service and the commands.
     */
    private void restoreThenRegister(BundleContext context, Parts parts, long restoreTimeoutMillis) {
        long deadline = System.currentTimeMillis() + restoreTimeoutMillis;
        try {
            if (!parts.installer().pending().isEmpty()) {
                // every index tried once, or every entry offered already: a slow index holds up no restore it is not
                // needed for
                while (!parts.repositories().awaitFirstAttempts(RESTORE_POLL_MS) && !parts.installer().pendingOffered()
                        && System.currentTimeMillis() < deadline) {
                    // look again
                }
                long left = deadline - System.currentTimeMillis();
                if (parts.installer().restore().timeout(Math.max(1, left)).getFailure() != null) {
                    log.warn("Bundle Installer: the journal's behaviours are not all back after {} ms; offering the"
                            + " service anyway, the restore goes on", restoreTimeoutMillis);
                } else if (!parts.installer().pending().isEmpty()) {
                    log.warn("Bundle Installer: offering the service without {} of the journal's behaviours, which"
                            + " cannot be installed now (see above, or 'bis:list'); tried again when an index changes",
                            parts.installer().pending().size());
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        } catch (RuntimeException e) {
            log.error("Bundle Installer: restoring the journal failed: {}", e.toString());
        }
        register(context, parts);
    }

    private synchronized void register(BundleContext context, Parts parts) {
        if (closed) {
            return;
        }
        try {
            registrations.add(context.registerService(BundleInstaller.class, parts.installer(), null));
            Hashtable<String, Object> props = new Hashtable<>();
            props.put("osgi.command.scope", "bis");
            props.put("osgi.command.function", new String[] { "list", "install", "uninstall", "stop", "allow", "repos" });
            registrations.add(context.registerService(BisCommands.class,
                    new BisCommands(parts.installer(), parts.repositories(),
                    parts.shellWaitMillis()), props));
        } catch (IllegalStateException e) {
            // the bundle is stopping: nothing to offer
        }
    }

    @Deactivate
    void deactivate() {
        synchronized (this) {
            closed = true;
            if (starter != null) {
                starter.interrupt();
            }
            for (ServiceRegistration<?> r : registrations) {
                try {
                    r.unregister();
                } catch (IllegalStateException e) {
                    // already gone with the bundle
                }
            }
            registrations.clear();
        }
        if (parts != null) {
            parts.repositories().close();
            parts.installer().close();
            parts.scheduler().shutdownNow();
            parts.callbacks().shutdownNow();
            parts.statistics().close();
            release(parts.journalLock());
        }
    }

    private void release(AutoCloseable lock) {
        try {
            lock.close();
        } catch (Exception e) {
            log.warn("Bundle Installer: could not release the journal's lock: {}", String.valueOf(e));
        }
    }

    private static URI parse(String url) {
        try {
            URI uri = URI.create(url);
            if (uri.getScheme() == null) {
                return Path.of(url).toAbsolutePath().toUri(); // a plain path is a file
            }
            return uri;
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("repositories: '" + url + "' is no URL (" + e.getMessage()
                    + "): give file:, http: or https: URLs of index files");
        }
    }

    /** Each configured value may hold several URLs separated by commas (a .cfg file's one string). */
    static List<URI> repositoryUrls(String[] configured) {
        List<URI> urls = new ArrayList<>();
        for (String value : configured) {
            if (value == null) {
                continue;
            }
            for (String url : value.split(",")) {
                if (!url.isBlank()) {
                    urls.add(parse(url.trim()));
                }
            }
        }
        return urls;
    }

    private static Path journalDir(BundleContext context, BisConfig config) {
        if (!config.journal_dir().isBlank()) {
            return Path.of(config.journal_dir());
        }
        return StateFolder.of(context::getProperty, System::getenv).resolve("bis");
    }

    private static ThreadFactory named(String name) {
        return r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        };
    }
}
