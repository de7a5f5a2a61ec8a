package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.federation.impl.InstallChoice.Offer;

/** The rule that picks the node that installs: a candidate at all, then the lowest load, then the lowest name. */
class InstallChoiceTest {

    static final List<BehaviourCandidate> ONE = List.of(FakeInstaller.candidate("x", "T"));

    @Test
    void onlyNodesThatOfferACandidateCount() {
        Offer chosen = InstallChoice.choose(List.of(new Offer("a", List.of(), 0), new Offer("b", null, 0),
                new Offer("c", ONE, 7)));
        assertThat(chosen.node()).isEqualTo("c");
    }

    @Test
    void theLowestLoadWins() {
        Offer chosen = InstallChoice.choose(List.of(new Offer("a", ONE, 3), new Offer("b", ONE, 1),
                new Offer("c", ONE, 2)));
        assertThat(chosen.node()).isEqualTo("b");
    }

    @Test
    void onEqualLoadTheLowestNodeNameWinsWhateverTheOrderOfAnswers() {
        List<Offer> offers = List.of(new Offer("node-2", ONE, 1), new Offer("node-10", ONE, 1),
                new Offer("node-1", ONE, 1), new Offer("a", ONE, 2));
        assertThat(InstallChoice.choose(offers).node()).isEqualTo("node-1");
        List<Offer> reversed = new java.util.ArrayList<>(offers);
        java.util.Collections.reverse(reversed);
        assertThat(InstallChoice.choose(reversed).node()).isEqualTo("node-1");
    }

    @Test
    void noOfferNoChoice() {
        assertThat(InstallChoice.choose(List.of())).isNull();
        assertThat(InstallChoice.choose(List.of(new Offer("a", List.of(), 0)))).isNull();
    }
}
