package eu.brain.iot.eventing.impl;

import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.namespace.PackageNamespace;
import org.osgi.framework.wiring.BundleCapability;
import org.osgi.framework.wiring.BundleWiring;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * The event type names this node knows, for a person's {@code bus:publish}: the types its behaviours consume, the
 * types that reached a behaviour or wait in the hold, and the classes of the packages its bundles export (read
 * from the bundles' entries; no class is loaded). Looked up on each call, only when a typed name is not found at
 * once; called on the shell's thread, holds no state.
 */
final class KnownEventTypes {

    private static final String CLASS_SUFFIX = ".class";

    private KnownEventTypes() {
    }

    /** Whether a consumer takes the type: the quick answer, before the bundles are read. */
    static boolean consumed(EventBusStatistics statistics, String eventType) {
        return statistics.consumers().stream().anyMatch(c -> c.consumed.contains(eventType));
    }

    static Set<String> all(BundleContext context, EventBusStatistics statistics) {
        Set<String> names = new TreeSet<>();
        statistics.consumers().forEach(c -> names.addAll(c.consumed));
        statistics.eventTypes().stream().filter(t -> t.delivered > 0 || t.held > 0).forEach(t -> names.add(t.eventType));
        for (Bundle bundle : context.getBundles()) {
            if (bundle.getBundleId() == Constants.SYSTEM_BUNDLE_ID) {
                continue; // the JDK's and the framework's packages: no event types there
            }
            BundleWiring wiring = bundle.adapt(BundleWiring.class);
            if (wiring == null) {
                continue; // not resolved: it exports nothing yet
            }
            for (BundleCapability export : wiring.getCapabilities(PackageNamespace.PACKAGE_NAMESPACE)) {
                Object pkg = export.getAttributes().get(PackageNamespace.PACKAGE_NAMESPACE);
                if (pkg instanceof String name) {
                    addClasses(wiring, name, names);
                }
            }
        }
        return names;
    }

    /**
     * The event class of that name, loaded from a bundle that exports its package, if one does and it is a
     * {@link BrainIoTEvent}: published as that class, the event reaches the consumers of its supertypes too.
     */
    static Optional<Class<? extends BrainIoTEvent>> eventClass(BundleContext context, String eventType) {
        int dot = eventType.lastIndexOf('.');
        if (dot < 0) {
            return Optional.empty();
        }
        String pkg = eventType.substring(0, dot);
        for (Bundle bundle : context.getBundles()) {
            BundleWiring wiring = bundle.getBundleId() == Constants.SYSTEM_BUNDLE_ID ? null
                    : bundle.adapt(BundleWiring.class);
            if (wiring != null && wiring.getCapabilities(PackageNamespace.PACKAGE_NAMESPACE).stream()
                    .anyMatch(c -> pkg.equals(c.getAttributes().get(PackageNamespace.PACKAGE_NAMESPACE)))) {
                try {
                    Class<?> type = bundle.loadClass(eventType);
                    if (BrainIoTEvent.class.isAssignableFrom(type)) {
                        return Optional.of(type.asSubclass(BrainIoTEvent.class));
                    }
                } catch (ClassNotFoundException | RuntimeException | LinkageError e) {
                    // not in this exporter (a split package) or not loadable: try the others
                }
            }
        }
        return Optional.empty();
    }

    private static void addClasses(BundleWiring wiring, String pkg, Set<String> names) {
        for (String path : wiring.listResources("/" + pkg.replace('.', '/'), "*" + CLASS_SUFFIX,
                BundleWiring.LISTRESOURCES_LOCAL)) {
            String className = path.substring(0, path.length() - CLASS_SUFFIX.length()).replace('/', '.');
            if (!className.contains("$") && !className.endsWith("package-info")) {
                names.add(className);
            }
        }
    }
}
