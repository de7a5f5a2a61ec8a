package eu.brain.iot.node.ready;

import org.osgi.framework.Bundle;

/**
 * How many of the framework's bundles, of some start levels, run as they should, and how: active bundles, fragments
 * (attached to their host: a fragment never becomes active), lazily activated bundles waiting for their first use.
 *
 * @param active bundles of the levels that are ACTIVE (the system bundle included)
 * @param fragments fragments of the levels, resolved
 * @param lazy lazily activated bundles of the levels still STARTING
 * @param installed every bundle installed in the framework, of any level
 */
record Census(int active, int fragments, int lazy, int installed) {

    static Census of(Bundle[] bundles, int maxStartLevel) {
        int active = 0;
        int fragments = 0;
        int lazy = 0;
        for (Bundle bundle : bundles) {
            if (BundleHealth.startLevel(bundle) > maxStartLevel) {
                continue;
            }
            int state = bundle.getState();
            if (state == Bundle.ACTIVE) {
                active++;
            } else if (state == Bundle.RESOLVED && BundleHealth.isFragment(bundle)) {
                fragments++;
            } else if (state == Bundle.STARTING && BundleHealth.isLazy(bundle)) {
                lazy++;
            }
        }
        return new Census(active, fragments, lazy, bundles.length);
    }

    /** Those of the levels that run as they should. */
    int running() {
        return active + fragments + lazy;
    }

    /**
     * {@code 37 of 41 bundles active}, {@code 35 of 41 bundles active, 2 fragments attached}; fragments and lazy
     * bundles are named apart, so that a count below the number installed never reads as a failed bundle.
     */
    String describe() {
        StringBuilder text = new StringBuilder().append(active).append(" of ").append(installed)
                .append(" bundles active");
        if (fragments > 0) {
            text.append(", ").append(fragments).append(fragments == 1 ? " fragment" : " fragments").append(" attached");
        }
        if (lazy > 0) {
            text.append(", ").append(lazy).append(lazy == 1 ? " lazy bundle" : " lazy bundles")
                    .append(" waiting for first use");
        }
        return text.toString();
    }
}
