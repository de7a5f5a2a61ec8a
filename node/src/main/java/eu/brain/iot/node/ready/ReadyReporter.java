package eu.brain.iot.node.ready;

import java.lang.management.ManagementFactory;
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
import org.osgi.framework.startlevel.FrameworkStartLevel;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;

import eu.brain.iot.eventing.api.EventBus;

/**
 * Prints the node's one "ready" line, with the time since the JVM started, as soon as the event bus is registered
 * and the launcher has started every bundle; names instead the bundles that are not active. Then it raises the
 * framework's start level, which starts what waits for the node to be ready: the Gogo shell, whose prompt thus
 * always follows this line, and bundles installed later, at the initial bundle start level.
 * <p>
 * The node's bndrun starts the framework at start level 1, so the launch is complete when bnd's launcher sets
 * {@code launcher.ready=true} on its service (it does so after starting every run bundle of that level), or,
 * under a launcher that starts the bundles before the framework, on {@link FrameworkEvent#STARTED}. Only bundles
 * up to this bundle's start level are checked. The bus reference is dynamic so that a bus that Config Admin
 * restarts at startup neither delays nor repeats the line.
 * <p>
 * With the framework property {@value #EXIT_WHEN_READY}{@code =true} the node stops right after the line, without
 * starting its shell, and the JVM exits with 0 when it was ready, 1 when a bundle is not active: a check for
 * scripts and CI. It hands the exit code to bnd's launcher as a {@code main.thread} {@link Callable}, which the
 * launcher runs, then stops the framework and exits with its result.
 * <p>
 * Ownership: {@link #buses}, {@link #launched} and {@link #reported} are guarded by {@code this}; the framework
 * calls in from its own threads.
 */
@Component
public final class ReadyReporter {

    /** Framework (or system) property: stop the node and exit once the ready line is printed. */
    public static final String EXIT_WHEN_READY = "fabric.node.exitWhenReady";

    private static final String LAUNCHER_READY = "(launcher.ready=true)";

    private final BundleContext context;
    private final long jvmStartMillis = ManagementFactory.getRuntimeMXBean().getStartTime();
    private final ServiceListener launcherListener = event -> {
        if (event.getType() == ServiceEvent.REGISTERED || event.getType() == ServiceEvent.MODIFIED) {
            launched();
        }
    };
    private final FrameworkListener frameworkListener = event -> {
        if (event.getType() == FrameworkEvent.STARTED) {
            launched();
        }
    };

    private int buses;
    private boolean launched;
    private boolean reported;

    @Activate
    public ReadyReporter(BundleContext context) throws InvalidSyntaxException {
        this.context = context;
        context.addFrameworkListener(frameworkListener);
        context.addServiceListener(launcherListener, LAUNCHER_READY);
        if (context.getServiceReferences((String) null, LAUNCHER_READY) != null) {
            launched();
        }
    }

    @Deactivate
    void deactivate() {
        context.removeServiceListener(launcherListener);
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
            if (reported || buses == 0 || !launched) {
                return;
            }
            reported = true;
        }
        long sinceJvmStart = System.currentTimeMillis() - jvmStartMillis;
        Bundle[] bundles = context.getBundles();
        List<String> problems = BundleHealth.problems(bundles, BundleHealth.startLevel(context.getBundle()));
        if (problems.isEmpty()) {
            System.out.printf("fabric node ready in %d ms (JVM start to event bus up, %d bundles); "
                    + "try bus:behaviours, bus:stats, lb, scr:list; 'stop 0' quits%n", sinceJvmStart, bundles.length);
        } else {
            System.out.printf("fabric node started in %d ms WITH PROBLEMS: %s%n", sinceJvmStart,
                    String.join("; ", problems));
        }
        if (Boolean.parseBoolean(context.getProperty(EXIT_WHEN_READY))) {
            exitWith(problems.isEmpty() ? 0 : 1);
        } else {
            startTheRest(bundles);
        }
    }

    /** Raises the framework to the highest start level in use, and at least to the one new bundles get. */
    private void startTheRest(Bundle[] bundles) {
        FrameworkStartLevel framework = context.getBundle(Constants.SYSTEM_BUNDLE_LOCATION)
                .adapt(FrameworkStartLevel.class);
        int level = framework.getInitialBundleStartLevel();
        for (Bundle bundle : bundles) {
            level = Math.max(level, BundleHealth.startLevel(bundle));
        }
        if (level > framework.getStartLevel()) {
            framework.setStartLevel(level);
        }
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
