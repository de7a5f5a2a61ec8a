package eu.brain.iot.bis.impl.journal;

import java.util.List;

/**
 * A behaviour the installer installed, as the journal keeps it: its own bundle is {@code bundles.get(0)}, the others
 * are what it needed from the repositories (possibly shared with other behaviours). Immutable.
 */
public record BehaviourRecord(String symbolicName, String version, List<String> consumed, String repository,
        long installedAt, String reason, List<BundleFact> bundles) {

    public BehaviourRecord {
        consumed = List.copyOf(consumed);
        bundles = List.copyOf(bundles);
    }

    public BundleFact own() {
        return bundles.get(0);
    }
}
