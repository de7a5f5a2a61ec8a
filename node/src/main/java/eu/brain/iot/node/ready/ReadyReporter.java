package eu.brain.iot.node.ready;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.FrameworkListener;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceEvent;
import org.osgi.framework.ServiceListener;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.startlevel.FrameworkStartLevel;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;

import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.node.state.StateHeld;

/**
 * Prints the node's "ready" line, with the time since the JVM started, as soon as the event bus is registered
 * and the launcher has started every bundle of the first start level (the node's core); names instead the bundles
 * that are not active. Then it raises the framework's start level, which starts what waits for the core: the
 * edge with its HTTP server, then the Gogo shell, whose prompt thus always comes last, and bundles installed
 * later, at the initial bundle start level. Once every level but the shell's is up it prints a second line,
 * "all bundles active", with its own time and, when the live dashboard's bundle is active, its address; or the
 * bundles that did not start.
 * <p>
 * The node's bndrun starts the framework at start level 1, so the launch is complete when bnd's launcher sets
 * {@code launcher.ready=true} on its service (it does so after starting every run bundle of that level), or,
 * under a launcher that starts the bundles before the framework, on {@link FrameworkEvent#STARTED}. The bus
 * reference is dynamic so that a bus that Config Admin restarts at startup neither delays nor repeats the line.
 * <p>
 * With the framework property {@value #EXIT_WHEN_READY}{@code =true} the node goes on to start every level below
 * the shell's, prints both lines, then stops, and the JVM exits with 0 when both found every bundle active, 1
 * otherwise: a check for scripts and CI. It hands the exit code to bnd's launcher as a {@code main.thread}
 * {@link Callable}, which the launcher runs, then stops the framework and exits with its result.
 * <p>
 * Besides the bus, the ready line waits for the services named by {@value #READY_SERVICES} (the node's bndrun names
 * the Bundle Installer, registered once its journal is restored, and the BMS's policy, both only when the installer
 * is configured: see {@link ReadyService}).
 * <p>
 * Ownership: {@link #buses}, {@link #launched}, {@link #reported}, {@link #coreHealthy}, {@link #fullLevel},
 * {@link #lastLevel} and {@link #shellLevel} are guarded by {@code this}; {@link #readyServices} is immutable; the
 * framework calls in from its own threads (each service event of a ready service looks again), and a check run's
 * deadline from its own ({@link #deadline}).
 */
@Component
public final class ReadyReporter {

    /** Framework (or system) property: stop the node and exit once the ready line is printed. */
    public static final String EXIT_WHEN_READY = "fabric.node.exitWhenReady";
    /**
     * Framework (or system) property: service interfaces (comma-separated) that must be registered, besides the
     * bus, before the ready line. The node's bndrun names the Bundle Installer, which registers its service only
     * once it has put back what its journal lists, and the Behaviour Management Service's policy: so a node that
     * says it is ready has its behaviours back and installs missing ones on demand.
     */
    public static final String READY_SERVICES = "fabric.node.ready.services";

    /**
     * Framework (or system) property: how many seconds a check run ({@value #EXIT_WHEN_READY}) waits for both lines;
     * then it says what it was still waiting for and exits with 1. A ready service that never comes (a behaviour
     * installer without its index, say) would otherwise hang the check.
     */
    public static final String CHECK_TIMEOUT = "fabric.node.check.timeout";
    static final long DEFAULT_CHECK_TIMEOUT_SECONDS = 120;

    private static final String LAUNCHER_READY = "(launcher.ready=true)";
    /** The shell reads the console: it starts last, and a check run stops before it. */
    private static final String SHELL = "org.apache.felix.gogo.shell";
    /** The Gogo shell's arguments (a framework property). */
    private static final String SHELL_ARGS = ReadyLines.SHELL_ARGS;

    private final BundleContext context;
    private final long jvmStartMillis = ManagementFactory.getRuntimeMXBean().getStartTime();
    private final ServiceListener launcherListener = event -> {
        if (event.getType() == ServiceEvent.REGISTERED || event.getType() == ServiceEvent.MODIFIED) {
            launched();
        }
    };
    /** Any registration or unregistration of a {@link #READY_SERVICES} service: look again. */
    private final ServiceListener readyServicesListener = event -> reportIfReady();
    private final List<ReadyService> readyServices;
    private final FrameworkListener frameworkListener = event -> {
        if (event.getType() == FrameworkEvent.STARTED) {
            launched();
        }
    };

    private int buses;
    private boolean launched;
    private boolean reported;
    private boolean coreHealthy;
    /** The level after which "all bundles active" is said; 0 until the ready line is out, -1 once said. */
    private int fullLevel;
    /** The level the node ends at: the shell's (or the initial bundle start level), not in a check. */
    private int lastLevel;
    /** The Gogo shell's start level, 0 without a shell bundle. */
    private int shellLevel;
    /** A check run's deadline (its own daemon thread), {@code null} otherwise. */
    private final ScheduledExecutorService deadline;

    /**
     * @param state the node's state folder, locked for it: without it (another node holds the folder) the node says
     *        why and ends, and this component never runs
     */
    @Activate
    public ReadyReporter(BundleContext context, @Reference StateHeld state) throws InvalidSyntaxException {
        this.context = context;
        this.readyServices = ReadyService.parse(context.getProperty(READY_SERVICES));
        if (!readyServices.isEmpty()) {
            StringBuilder filter = new StringBuilder("(|");
            readyServices.forEach(s -> filter.append("(objectClass=").append(s.name()).append(')'));
            context.addServiceListener(readyServicesListener, filter.append(')').toString());
        }
        if (Boolean.parseBoolean(context.getProperty(EXIT_WHEN_READY))) {
            long seconds = checkTimeoutSeconds(context.getProperty(CHECK_TIMEOUT));
            deadline = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread thread = new Thread(r, "fabric-node-check-deadline");
                thread.setDaemon(true);
                return thread;
            });
            deadline.schedule(() -> giveUp(seconds), seconds, TimeUnit.SECONDS);
        } else {
            deadline = null;
        }
        context.addFrameworkListener(frameworkListener);
        context.addServiceListener(launcherListener, LAUNCHER_READY);
        if (context.getServiceReferences((String) null, LAUNCHER_READY) != null) {
            launched();
        }
    }

    @Deactivate
    void deactivate() {
        context.removeServiceListener(launcherListener);
        context.removeServiceListener(readyServicesListener);
        context.removeFrameworkListener(frameworkListener);
        if (deadline != null) {
            deadline.shutdownNow();
        }
    }

    /** The check's deadline in seconds: the property's value, or the default when it is missing or not a number. */
    static long checkTimeoutSeconds(String property) {
        if (property == null || property.isBlank()) {
            return DEFAULT_CHECK_TIMEOUT_SECONDS;
        }
        try {
            long seconds = Long.parseLong(property.trim());
            if (seconds > 0) {
                return seconds;
            }
        } catch (NumberFormatException e) {
            // below
        }
        System.out.printf("fabric node: %s=%s is not a number of seconds above 0; the check waits %d s%n",
                CHECK_TIMEOUT, property, DEFAULT_CHECK_TIMEOUT_SECONDS);
        return DEFAULT_CHECK_TIMEOUT_SECONDS;
    }

    /** A check run's deadline passed before both lines were out: say what is missing, and exit with 1. */
    private void giveUp(long seconds) {
        List<String> waiting;
        synchronized (this) {
            if (fullLevel < 0) {
                return; // both lines are out (or on their way): the check ends by itself
            }
            waiting = waitingFor();
            reported = true;
            fullLevel = -1;
        }
        System.out.printf("fabric node: check run gave up after %d s (%s), still waiting for: %s%n", seconds,
                CHECK_TIMEOUT + "=" + seconds, String.join("; ", waiting));
        exitWith(1);
    }

    /** What the lines still wait for. Called under {@code this}. */
    private List<String> waitingFor() {
        List<String> waiting = new java.util.ArrayList<>();
        if (!launched) {
            waiting.add("the launcher to start every bundle of the first start level");
        }
        if (buses == 0) {
            waiting.add("the event bus (" + EventBus.class.getName() + ")");
        }
        for (ReadyService service : readyServices) {
            try {
                if (required(service) && context.getServiceReferences(service.name(), null) == null) {
                    waiting.add("service " + service.name() + " (" + READY_SERVICES + ")");
                }
            } catch (InvalidSyntaxException | IllegalStateException e) {
                waiting.add("service " + service.name() + " (" + e.getMessage() + ")");
            }
        }
        FrameworkStartLevel framework = context.getBundle(Constants.SYSTEM_BUNDLE_LOCATION)
                .adapt(FrameworkStartLevel.class);
        if (fullLevel > 0 && framework.getStartLevel() < fullLevel) {
            waiting.add("start level " + fullLevel + " (at " + framework.getStartLevel() + ")");
        }
        int max = fullLevel > 0 ? fullLevel : BundleHealth.startLevel(context.getBundle());
        waiting.addAll(BundleHealth.problems(context.getBundles(), max));
        if (waiting.isEmpty()) {
            waiting.add("the framework to report its start level (every bundle looks active)");
        }
        return waiting;
    }

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC, unbind = "busGone")
    void busUp(EventBus bus) {
        synchronized (this) {
            buses++;
        }
        reportIfReady();
    }

    void busGone(EventBus bus) {
        synchronized (this) {
            buses--;
        }
    }

    private void launched() {
        synchronized (this) {
            launched = true;
        }
        reportIfReady();
    }

    private void reportIfReady() {
        synchronized (this) {
            if (reported || buses == 0 || !launched || !readyServicesUp()) {
                return;
            }
            reported = true;
        }
        long sinceJvmStart = System.currentTimeMillis() - jvmStartMillis;
        Bundle[] bundles = context.getBundles();
        int core = BundleHealth.startLevel(context.getBundle());
        List<String> problems = BundleHealth.problems(bundles, core);
        if (problems.isEmpty()) {
            System.out.println(ReadyLines.readyLine(sinceJvmStart, waitedFor(), core, Census.of(bundles, core),
                    ReadyLines.howToUse(Boolean.parseBoolean(context.getProperty(EXIT_WHEN_READY)),
                            context.getProperty(SHELL_ARGS), ProcessHandle.current().pid())));
        } else {
            System.out.printf("fabric node started in %d ms WITH PROBLEMS: %s%n", sinceJvmStart,
                    String.join("; ", problems));
        }
        boolean check = Boolean.parseBoolean(context.getProperty(EXIT_WHEN_READY));
        int highest = 0;
        int shell = 0;
        for (Bundle bundle : bundles) {
            int level = BundleHealth.startLevel(bundle);
            highest = Math.max(highest, level);
            if (SHELL.equals(bundle.getSymbolicName())) {
                shell = level;
            }
        }
        // Everything of the node's own starts below the shell; at the shell's level also the bundles dropped in
        // the config folder (File Install), which are the user's, not the node's.
        int full = shell > 1 ? shell - 1 : highest;
        FrameworkStartLevel framework = context.getBundle(Constants.SYSTEM_BUNDLE_LOCATION)
                .adapt(FrameworkStartLevel.class);
        synchronized (this) {
            if (fullLevel < 0) {
                return; // a check run gave up meanwhile
            }
            coreHealthy = problems.isEmpty();
            fullLevel = full;
            shellLevel = shell;
            lastLevel = check ? full : Math.max(highest, framework.getInitialBundleStartLevel());
        }
        if (full > framework.getStartLevel()) {
            // told when this change is complete: a STARTLEVEL_CHANGED of an earlier change (the launcher's to level 1)
            // may still be on its way, and the framework already reports the new level while starting its bundles
            framework.setStartLevel(full, event -> levelReached());
        } else {
            levelReached();
        }
    }

    /** Whether every ready service that is required now (configured, when it names a PID) is registered. */
    private boolean readyServicesUp() {
        for (ReadyService service : readyServices) {
            try {
                if (required(service) && context.getServiceReferences(service.name(), null) == null) {
                    return false;
                }
            } catch (InvalidSyntaxException | IllegalStateException e) {
                return false;
            }
        }
        return true;
    }

    /** A service that depends on a configuration is waited for only when Config Admin holds it. */
    private boolean required(ReadyService service) {
        if (service.pid() == null) {
            return true;
        }
        ServiceReference<ConfigurationAdmin> ref = context.getServiceReference(ConfigurationAdmin.class);
        ConfigurationAdmin configAdmin = ref == null ? null : context.getService(ref);
        if (configAdmin == null) {
            return false;
        }
        try {
            return configAdmin.listConfigurations("(service.pid=" + service.pid() + ")") != null;
        } catch (IOException | InvalidSyntaxException e) {
            return false;
        } finally {
            context.ungetService(ref);
        }
    }

    /** What the ready line says it waited for besides the bus. */
    private String waitedFor() {
        List<String> names = new java.util.ArrayList<>();
        for (ReadyService service : readyServices) {
            if (required(service)) {
                names.add(service.name());
            }
        }
        return names.isEmpty() ? "" : " and " + ReadyLines.describe(names);
    }

    /** After a start level change: once every level but the shell's is up, say whether every bundle is active. */
    private void levelReached() {
        FrameworkStartLevel framework = context.getBundle(Constants.SYSTEM_BUNDLE_LOCATION)
                .adapt(FrameworkStartLevel.class);
        int level;
        int last;
        int shell;
        boolean core;
        synchronized (this) {
            if (fullLevel <= 0 || framework.getStartLevel() < fullLevel) {
                return;
            }
            level = fullLevel;
            last = lastLevel;
            shell = shellLevel;
            fullLevel = -1;
            core = coreHealthy;
        }
        long sinceJvmStart = System.currentTimeMillis() - jvmStartMillis;
        Bundle[] bundles = context.getBundles();
        // The levels above the core's (the core was looked at for the ready line) up to the shell's, at which
        // File Install also starts the bundles dropped in the config folder.
        List<String> problems = new java.util.ArrayList<>(BundleHealth.problems(bundles,
                BundleHealth.startLevel(context.getBundle()) + 1, level));
        problems.addAll(HttpHealth.problems(context, bundles));
        if (problems.isEmpty()) {
            Census census = Census.of(bundles, level);
            System.out.println(ReadyLines.upLine(sinceJvmStart, level, census, dashboardLink(bundles)
                    + ReadyLines.whatIsNext(Boolean.parseBoolean(context.getProperty(EXIT_WHEN_READY)),
                            context.getProperty(SHELL_ARGS), shell, census.installed() - census.running())));
        } else {
            System.out.printf("fabric node: started in %d ms WITH PROBLEMS: %s%n", sinceJvmStart,
                    String.join("; ", problems));
        }
        if (Boolean.parseBoolean(context.getProperty(EXIT_WHEN_READY))) {
            exitWith(core && problems.isEmpty() ? 0 : 1);
        } else if (last > framework.getStartLevel()) {
            framework.setStartLevel(last); // the shell last, so that its prompt follows both lines
        }
    }

    /** Where the live dashboard is, when its bundle is active; else nothing. */
    private String dashboardLink(Bundle[] bundles) {
        for (Bundle bundle : bundles) {
            if (ReadyLines.DASHBOARD.equals(bundle.getSymbolicName()) && bundle.getState() == Bundle.ACTIVE) {
                return ReadyLines.dashboard(context.getProperty(ReadyLines.HTTP_HOST),
                        context.getProperty(ReadyLines.HTTP_PORT));
            }
        }
        return "";
    }

    private void exitWith(int status) {
        Dictionary<String, Object> properties = new Hashtable<>();
        properties.put("main.thread", Boolean.TRUE);
        context.registerService(Callable.class, new ExitCode(status), properties);
    }

    /** A named class: bnd's launcher checks the main thread service's declared type, {@code Callable<Integer>}. */
    private static final class ExitCode implements Callable<Integer> {
        private final int status;

        ExitCode(int status) {
            this.status = status;
        }

        @Override
        public Integer call() {
            return status;
        }
    }
}
