package eu.brain.iot.bis.integration;

import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyPair;
import java.time.Duration;
import java.util.Comparator;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;
import org.osgi.util.promise.Promise;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.sign.IndexSigning;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * What every in-framework test of the installer shares: a copy of the real test index in a temporary directory, a
 * fresh journal directory, the installer configured through Config Admin, and a clean-up that uninstalls whatever
 * the test installed and removes the configuration.
 * <p>
 * The configuration is written here, not by osgi-test's {@code @WithConfiguration}/{@code @InjectConfiguration}:
 * those create the configuration before the test from constants, and the installer's is made per test (a fresh copy
 * of the index, a freshly generated signing key, a fresh journal directory) and changed, removed and written again
 * within a test (a restart of the installer). A constant placeholder configured before the test would start an
 * installer on the default journal directory (the user's own, {@code ~/.local/state/brain-iot}). Nor can osgi-test
 * undo the installs: the installer installs through its own bundle context, not the test's closeable one.
 */
abstract class BisTestBase {

    static final String PID = "eu.brain.iot.bis";
    static final Duration DEADLINE = Duration.ofSeconds(30);

    @InjectBundleContext
    BundleContext context;
    @InjectService
    ConfigurationAdmin configAdmin;
    @InjectService
    EventBusStatistics busStatistics;

    Path temp;
    TestRepository repo;
    KeyPair keys;
    Path journal;
    private Configuration configuration;
    private long lastInstallerId = -1;

    @BeforeEach
    void prepare() throws Exception {
        temp = Files.createTempDirectory("bis-test");
        repo = TestRepository.copy(context.getProperty("bis.test.repository"), temp.resolve("repo"));
        keys = IndexSigning.generateKeyPair();
        repo.sign(keys);
        journal = temp.resolve("journal");
    }

    @AfterEach
    void cleanUp() throws Exception {
        BundleInstaller installer = currentInstaller();
        if (installer != null) {
            for (InstalledBehaviour b : installer.installed()) {
                installer.uninstall(b.symbolicName, "test clean-up", false).getValue();
            }
        }
        if (configuration != null) {
            configuration.delete();
            await().atMost(DEADLINE).until(() -> context.getServiceReference(BundleInstaller.class) == null);
        }
        try (Stream<Path> files = Files.walk(temp)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }

    /** The usual configuration: the signed copy of the index, its key trusted, short refresh and retry times. */
    Map<String, Object> settings() throws IOException {
        return new java.util.HashMap<>(Map.of(
                "repositories", new String[] { repo.index.toUri().toString() },
                "trusted.keys", new String[] { repo.publicKey(keys, "trusted").toString() },
                "journal.dir", journal.toString(),
                "refresh.ms", 100L,
                "retry.initial.ms", 50L,
                "retry.max.ms", 400L,
                "activation.timeout.ms", 10_000L));
    }

    /** (Re)configures the installer and waits for the new instance's service (after its journal is restored). */
    BundleInstaller configure(Map<String, Object> settings) throws IOException {
        if (configuration == null) {
            configuration = configAdmin.getConfiguration(PID, "?");
        }
        Dictionary<String, Object> properties = new Hashtable<>(settings);
        long previous = lastInstallerId;
        configuration.update(properties);
        await().atMost(DEADLINE).until(() -> installerId() > previous);
        lastInstallerId = installerId();
        return currentInstaller();
    }

    /** Configures the installer without waiting for its service (which a bad configuration never brings). */
    void configureOnly(Map<String, Object> settings) throws IOException {
        if (configuration == null) {
            configuration = configAdmin.getConfiguration(PID, "?");
        }
        configuration.update(new Hashtable<>(settings));
    }

    /** @return the messages the log service holds, newest first */
    List<String> logMessages() {
        ServiceReference<org.osgi.service.log.LogReaderService> ref = context
                .getServiceReference(org.osgi.service.log.LogReaderService.class);
        List<String> messages = new java.util.ArrayList<>();
        java.util.Enumeration<org.osgi.service.log.LogEntry> log = context.getService(ref).getLog();
        while (log.hasMoreElements()) {
            messages.add(log.nextElement().getMessage());
        }
        return messages;
    }

    /** Removes the configuration: the installer goes away (its bundles stay, as they would until a node restart). */
    void unconfigure() throws IOException {
        configuration.delete();
        configuration = null;
        await().atMost(DEADLINE).until(() -> context.getServiceReference(BundleInstaller.class) == null);
    }

    BundleInstaller currentInstaller() {
        ServiceReference<BundleInstaller> ref = context.getServiceReference(BundleInstaller.class);
        return ref == null ? null : context.getService(ref);
    }

    private long installerId() {
        ServiceReference<BundleInstaller> ref = context.getServiceReference(BundleInstaller.class);
        return ref == null ? -1 : (Long) ref.getProperty("service.id");
    }

    /** Waits until the installer's indexes offer a behaviour consuming the type. */
    void awaitOffered(BundleInstaller installer, String type) {
        await().atMost(DEADLINE).until(() -> !installer.find(List.of(type)).getValue().isEmpty());
    }

    static InstallRequest byType(String... types) {
        InstallRequest request = new InstallRequest();
        request.consumedTypes = List.of(types);
        request.reason = "test: event had no consumer";
        return request;
    }

    static InstallRequest byName(String symbolicName, boolean operator) {
        InstallRequest request = new InstallRequest();
        request.symbolicName = symbolicName;
        request.operator = operator;
        request.reason = "test";
        return request;
    }

    /** @return the failure of a promise, waiting for it */
    static InstallException failure(Promise<?> promise) throws InterruptedException {
        Throwable failure = promise.getFailure();
        if (failure instanceof InstallException e) {
            return e;
        }
        throw new AssertionError("expected an InstallException, got " + failure);
    }

    static <T> T value(Promise<T> promise) throws Exception {
        try {
            return promise.getValue();
        } catch (InvocationTargetException e) {
            throw new AssertionError("the promise failed: " + e.getCause().getMessage(), e.getCause());
        }
    }

    /** Every bundle of the framework: id, name, version and state. */
    Set<String> frameworkBundles() {
        Set<String> all = new TreeSet<>();
        for (Bundle b : context.getBundles()) {
            all.add(b.getBundleId() + " " + b.getSymbolicName() + " " + b.getVersion() + " " + b.getState());
        }
        return all;
    }

    Bundle bundle(String symbolicName) {
        for (Bundle b : context.getBundles()) {
            if (symbolicName.equals(b.getSymbolicName())) {
                return b;
            }
        }
        return null;
    }

    long bundleCount(String symbolicName) {
        return Stream.of(context.getBundles()).filter(b -> symbolicName.equals(b.getSymbolicName())).count();
    }

    /** Whether the bus lists a smart behaviour of that bundle. */
    boolean busKnows(String symbolicName) {
        return busStatistics.consumers().stream().anyMatch(c -> symbolicName.equals(c.bundle));
    }

    /**
     * Calls a bis:* Gogo command function and returns its text. The command object is a service of its own, which
     * may come a moment after the installer's (a new configuration restarts both): it is waited for.
     */
    String command(String function, Object... args) throws Exception {
        ServiceReference<?>[] refs = await().atMost(DEADLINE).until(
                () -> context.getServiceReferences((String) null, "(osgi.command.scope=bis)"), r -> r != null);
        Object commands = context.getService(refs[0]);
        for (var m : commands.getClass().getMethods()) {
            if (m.getName().equals(function) && m.getParameterCount() == args.length) {
                return String.valueOf(m.invoke(commands, args));
            }
        }
        throw new AssertionError("no command bis:" + function);
    }
}
