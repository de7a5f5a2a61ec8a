package eu.brain.iot.bis.impl.install;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Version;

import eu.brain.iot.bis.impl.repo.BehaviourResource;

class ChoicePolicyTest {

    private static final URI A = URI.create("file:/a/index.xml");
    private static final URI B = URI.create("file:/b/index.xml");

    private static BehaviourResource behaviour(String name, String version, URI repo, String... consumed) {
        return new BehaviourResource(null, name, Version.parseVersion(version), repo.resolve(name + ".jar"), "00", 1,
                List.of(consumed), repo);
    }

    @Test
    void preferencesFirstThenHighestVersionThenName() {
        List<BehaviourResource> all = List.of(behaviour("x.old", "1.0", A, "T"), behaviour("x.new", "2.0", A, "T"),
                behaviour("x.pref", "0.1", A, "T"), behaviour("x.other", "9.0", A, "U"),
                behaviour("x.same", "2.0", A, "T"));

        assertThat(new ChoicePolicy(List.of()).byConsumedTypes(all, List.of("T")))
                .extracting(BehaviourResource::symbolicName).containsExactly("x.new", "x.same", "x.old", "x.pref");
        assertThat(new ChoicePolicy(List.of("x.pref", "x.old")).byConsumedTypes(all, List.of("T")))
                .extracting(BehaviourResource::symbolicName).containsExactly("x.pref", "x.old", "x.new", "x.same");
    }

    @Test
    void aBehaviourInTwoIndexesCountsOnceFromTheFirstAndVersionRangesFilter() {
        List<BehaviourResource> all = List.of(behaviour("x", "1.0", A, "T"), behaviour("x", "1.0", B, "T"),
                behaviour("x", "2.0", B, "T"));
        ChoicePolicy policy = new ChoicePolicy(List.of());

        assertThat(policy.byName(all, "x", null)).extracting(r -> r.version() + " " + r.repository())
                .containsExactly("2.0.0 " + B, "1.0.0 " + A);
        assertThat(policy.byName(all, "x", "[1,2)")).extracting(r -> r.version().toString()).containsExactly("1.0.0");
    }
}
