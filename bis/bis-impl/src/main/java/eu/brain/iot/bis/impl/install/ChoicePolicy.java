package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.osgi.framework.VersionRange;

import eu.brain.iot.bis.impl.repo.BehaviourResource;

/**
 * Which behaviour to install when several fit: first those named in the configured {@code prefer} list, in its
 * order; then the highest version; then the symbolic name (alphabetically, so that the choice is repeatable). The
 * same symbolic name and version in several indexes counts once, from the first index in configuration order.
 * Immutable; thread-safe.
 */
public final class ChoicePolicy {

    private final List<String> prefer;

    public ChoicePolicy(List<String> prefer) {
        this.prefer = List.copyOf(prefer);
    }

    /** @return the behaviours that consume any of {@code types}, best first */
    public List<BehaviourResource> byConsumedTypes(List<BehaviourResource> resources, List<String> types) {
        return order(resources.stream().filter(r -> r.consumed().stream().anyMatch(types::contains)).toList());
    }

    /** @return the behaviours with that symbolic name whose version is in the range (null: any), best first */
    public List<BehaviourResource> byName(List<BehaviourResource> resources, String symbolicName, String range) {
        VersionRange versions = range == null || range.isBlank() ? null : VersionRange.valueOf(range);
        return order(resources.stream().filter(r -> r.symbolicName().equals(symbolicName))
                .filter(r -> versions == null || versions.includes(r.version())).toList());
    }

    private List<BehaviourResource> order(List<BehaviourResource> fitting) {
        Set<String> seen = new HashSet<>();
        List<BehaviourResource> unique = new ArrayList<>();
        for (BehaviourResource r : fitting) {
            if (seen.add(r.symbolicName() + ";" + r.version())) {
                unique.add(r);
            }
        }
        unique.sort(Comparator.comparingInt(this::rank)
                .thenComparing(BehaviourResource::version, Comparator.reverseOrder())
                .thenComparing(BehaviourResource::symbolicName));
        return unique;
    }

    private int rank(BehaviourResource r) {
        int i = prefer.indexOf(r.symbolicName());
        return i < 0 ? Integer.MAX_VALUE : i;
    }
}
