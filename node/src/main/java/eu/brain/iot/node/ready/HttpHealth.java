package eu.brain.iot.node.ready;

import java.util.List;
import java.util.concurrent.TimeUnit;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;

/**
 * Whether the node's HTTP server listens. Felix HTTP's bundle stays ACTIVE when Jetty cannot bind its port (another
 * node, or any program, has it): it logs the BindException and registers no {@code HttpServiceRuntime}. So the
 * server is up when that bundle registered its runtime service, and the node names the port and what to pass instead
 * when it did not. Stateless.
 */
final class HttpHealth {

    static final String JETTY = "org.apache.felix.http.jetty";
    private static final String RUNTIME = "org.osgi.service.http.runtime.HttpServiceRuntime";
    /** Felix HTTP registers its runtime while its bundle starts; a moment's grace for a restart by configuration. */
    private static final long GRACE_MS = 1_000;
    private static final long POLL_MS = 50;

    private HttpHealth() {
    }

    /** One line when the HTTP bundle is active but its server is not listening; empty otherwise. */
    static List<String> problems(BundleContext context, Bundle[] bundles) {
        Bundle jetty = null;
        for (Bundle bundle : bundles) {
            if (JETTY.equals(bundle.getSymbolicName()) && bundle.getState() == Bundle.ACTIVE) {
                jetty = bundle;
            }
        }
        if (jetty == null) {
            return List.of(); // no HTTP server in this node, or BundleHealth names its bundle already
        }
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(GRACE_MS);
        while (!listening(context, jetty)) {
            if (System.nanoTime() > deadline) {
                String host = context.getProperty(ReadyLines.HTTP_HOST);
                String port = context.getProperty(ReadyLines.HTTP_PORT);
                return List.of("the HTTP server (REST API, dashboard) is not listening: port " + port + " on "
                        + (host == null ? "all addresses" : host) + " could not be bound (another node or program"
                        + " uses it; see the BindException above); start with another port: ./fabric-node"
                        + " --http-port=N (or -D" + ReadyLines.HTTP_PORT + "=N)");
            }
            try {
                Thread.sleep(POLL_MS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return List.of("interrupted while looking whether the HTTP server listens");
            }
        }
        return List.of();
    }

    private static boolean listening(BundleContext context, Bundle jetty) {
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(RUNTIME, null);
            if (refs != null) {
                for (ServiceReference<?> ref : refs) {
                    if (ref.getBundle() != null && ref.getBundle().getBundleId() == jetty.getBundleId()) {
                        return true;
                    }
                }
            }
            return false;
        } catch (InvalidSyntaxException | IllegalStateException e) {
            return false;
        }
    }
}
