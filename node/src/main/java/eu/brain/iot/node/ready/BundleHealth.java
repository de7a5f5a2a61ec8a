package eu.brain.iot.node.ready;

import java.util.ArrayList;
import java.util.List;

import org.osgi.framework.Bundle;
import org.osgi.framework.Constants;
import org.osgi.framework.startlevel.BundleStartLevel;
import org.osgi.framework.wiring.BundleRevision;

/** Which bundles of a framework are not running as they should once the launcher has started them all. */
final class BundleHealth {

    private BundleHealth() {
    }

    /**
     * One line per bundle up to the given start level that should be active and is not; empty when the node is
     * healthy. Fragments only need to be resolved, and a lazily activated bundle may wait in STARTING for its
     * first class load. Bundles above {@code maxStartLevel} are started later on purpose and are not looked at.
     */
    static List<String> problems(Bundle[] bundles, int maxStartLevel) {
        return problems(bundles, 0, maxStartLevel);
    }

    /** The same, for the bundles of start levels {@code minStartLevel} to {@code maxStartLevel} only. */
    static List<String> problems(Bundle[] bundles, int minStartLevel, int maxStartLevel) {
        List<String> problems = new ArrayList<>();
        for (Bundle bundle : bundles) {
            int level = startLevel(bundle);
            if (level < minStartLevel || level > maxStartLevel) {
                continue;
            }
            int state = bundle.getState();
            if (state == Bundle.ACTIVE || (state == Bundle.RESOLVED && isFragment(bundle))
                    || (state == Bundle.STARTING && isLazy(bundle))) {
                continue;
            }
            problems.add(String.format("bundle %s %s (id %d) is %s", bundle.getSymbolicName(), bundle.getVersion(),
                    bundle.getBundleId(), advice(state, bundle.getBundleId())));
        }
        return problems;
    }

    private static String advice(int state, long id) {
        return switch (state) {
            case Bundle.INSTALLED -> "not resolved (a requirement is missing): type 'start " + id
                    + "' in the shell to see which";
            case Bundle.RESOLVED -> "resolved but not started (its activator failed?): type 'start " + id
                    + "' in the shell to see why";
            case Bundle.STARTING -> "still starting (its activator blocks)";
            case Bundle.STOPPING -> "stopping";
            default -> "in state " + state;
        };
    }

    static int startLevel(Bundle bundle) {
        BundleStartLevel level = bundle.adapt(BundleStartLevel.class);
        return level == null ? 0 : level.getStartLevel();
    }

    static boolean isFragment(Bundle bundle) {
        BundleRevision revision = bundle.adapt(BundleRevision.class);
        return revision != null && (revision.getTypes() & BundleRevision.TYPE_FRAGMENT) != 0;
    }

    static boolean isLazy(Bundle bundle) {
        String policy = bundle.getHeaders("").get(Constants.BUNDLE_ACTIVATIONPOLICY);
        return policy != null && policy.startsWith(Constants.ACTIVATION_LAZY);
    }
}
