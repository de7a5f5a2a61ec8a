package eu.brain.iot.node.ready;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.Callable;

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

/**
 * Prints the node's "ready" line, with the time since the JVM started, as soon as the event bus is registered
 * and the launcher has started every bundle of the first start level (the node's core); names instead the bundles
 * that are not active. Then it raises the framework's start level, which starts what waits for the core: the
 * edge with its HTTP server, then the Gogo shell, whose prompt thus always comes last, and bundles installed
 * later, at the initial bundle start level. Once every level but the shell's is up it prints a second line,
 * "all bundles active", with its own time, or the bundles that did not start.
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
 * Ownership: {@link #buses}, {@link #launched}, {@link #reported}, {@link #coreHealthy}, {@link #fullLevel} and
 * {@link #lastLevel} are guarded by {@code this}; {@link #readyServices} is immutable; the framework calls in from its
 * own threads (each service event of a ready service looks again).
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

    private static final String LAUNCHER_READY = "(launcher.ready=true)";
    /** The shell reads the console: it starts last, and a check run stops before it. */
    private static final String SHELL = "org.apache.felix.gogo.shell";
    /** The Gogo shell's arguments (a framework property); with {@value #NO_INTERACTIVE} it reads no console. */
    private static final String SHELL_ARGS = "gosh.args";
    private static final String NO_INTERACTIVE = "--nointeractive";

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
        } else if (event.getType() == FrameworkEvent.STARTLEVEL_CHANGED) {
            levelReached();
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

    @Activate
    public ReadyReporter(BundleContext context) throws InvalidSyntaxException {
        this.context = context;
        this.readyServices = ReadyService.parse(context.getProperty(READY_SERVICES));
        if (!readyServices.isEmpty()) {
            StringBuilder filter = new StringBuilder("(|");
            readyServices.forEach(s -> filter.append("(objectClass=").append(s.name()).append(')'));
            context.addServiceListener(readyServicesListener, filter.append(')').toString());
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
        List<String> problems = BundleHealth.problems(bundles, BundleHealth.startLevel(context.getBundle()));
        if (problems.isEmpty()) {
            System.out.printf("fabric node ready in %d ms (JVM start to event bus%s up, %d bundles installed); %s%n",
                    sinceJvmStart, waitedFor(), bundles.length,
                    howToUse(Boolean.parseBoolean(context.getProperty(EXIT_WHEN_READY)),
                            context.getProperty(SHELL_ARGS), ProcessHandle.current().pid()));
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
            coreHealthy = problems.isEmpty();
            fullLevel = full;
            lastLevel = check ? full : Math.max(highest, framework.getInitialBundleStartLevel());
        }
        if (full > framework.getStartLevel()) {
            framework.setStartLevel(full);
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
        return names.isEmpty() ? "" : " and " + describe(names);
    }

    /** After a start level change: once every level but the shell's is up, say whether every bundle is active. */
    private void levelReached() {
        FrameworkStartLevel framework = context.getBundle(Constants.SYSTEM_BUNDLE_LOCATION)
                .adapt(FrameworkStartLevel.class);
        int level;
        int last;
        boolean core;
        synchronized (this) {
            if (fullLevel <= 0 || framework.getStartLevel() < fullLevel) {
                return;
            }
            level = fullLevel;
            last = lastLevel;
            fullLevel = -1;
            core = coreHealthy;
        }
        long sinceJvmStart = System.currentTimeMillis() - jvmStartMillis;
        Bundle[] bundles = context.getBundles();
        // The levels above the core's (the core was looked at for the ready line) up to the shell's, at which
        // File Install also starts the bundles dropped in the config folder.
        List<String> problems = BundleHealth.problems(bundles, BundleHealth.startLevel(context.getBundle()) + 1,
                level);
        if (problems.isEmpty()) {
            // Only the bundles started so far: the shell's level (and File Install's bundles) come after this line.
            long started = Arrays.stream(bundles).filter(b -> BundleHealth.startLevel(b) <= level).count();
            System.out.printf("fabric node: all %d bundles active in %d ms (start levels 1 to %d: the core, then "
                    + "the edge and its REST API)%n", started, sinceJvmStart, level);
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

    /** How the ready line names what it waited for besides the bus. */
    static String describe(List<String> services) {
        List<String> names = new java.util.ArrayList<>();
        for (String service : services) {
            names.add(switch (service) {
            case "eu.brain.iot.bis.api.BundleInstaller" -> "behaviour installer (journal restored)";
            case "eu.brain.iot.eventing.spi.UnhandledEventPolicy" -> "behaviour management";
            default -> service.substring(service.lastIndexOf('.') + 1);
            });
        }
        return String.join(" and ", names);
    }

    /**
     * The end of the ready line: what to type, and how to stop the node. Without an interactive shell (the Gogo
     * shell's {@code --nointeractive}, as {@code ./fabric-node --no-shell} sets) there is nothing to type into:
     * the node runs until its process is stopped.
     */
    static String howToUse(boolean check, String shellArgs, long pid) {
        if (check) {
            return "check run: stops once every bundle is active";
        }
        if (shellArgs != null && List.of(shellArgs.trim().split("\\s+")).contains(NO_INTERACTIVE)) {
            return "no shell (" + SHELL_ARGS + "=" + NO_INTERACTIVE + "): stop it with Ctrl-C or kill " + pid;
        }
        return "try bus:behaviours, bus:publish, bis:list, bms:pending, edge:robots, lb; 'stop 0' quits";
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
