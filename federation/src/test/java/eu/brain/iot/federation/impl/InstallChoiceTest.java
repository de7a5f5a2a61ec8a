package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.federation.impl.InstallChoice.Offer;

/**
 * The rule that picks the node that installs: a candidate at all, then the most devices the event names owned, then
 * the lowest load, then the lowest name.
 */
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
    void theNodeThatOwnsTheDevicesTheEventNamesWinsOverALowerLoadAndALowerName() {
        Offer chosen = InstallChoice.choose(List.of(new Offer("a", ONE, 0), new Offer("b", ONE, 5, List.of("robot2")),
                new Offer("c", ONE, 1)));
        assertThat(chosen.node()).isEqualTo("b");
    }

    @Test
    void owningWithoutACandidateCountsForNothing() {
        Offer chosen = InstallChoice.choose(List.of(new Offer("a", ONE, 3), new Offer("b", List.of(), 0,
                List.of("robot2")), new Offer("c", null, 0, List.of("robot2"))));
        assertThat(chosen.node()).isEqualTo("a");
    }

    @Test
    void theNodeThatOwnsMoreOfTheNamedDevicesWinsThenLoadThenName() {
        assertThat(InstallChoice.choose(List.of(new Offer("a", ONE, 0, List.of("door1")),
                new Offer("b", ONE, 9, List.of("door1", "robot2")))).node()).isEqualTo("b");
        assertThat(InstallChoice.choose(List.of(new Offer("a", ONE, 2, List.of("robot2")),
                new Offer("b", ONE, 1, List.of("door1")))).node()).as("one each: the lower load").isEqualTo("b");
        List<Offer> tie = List.of(new Offer("node-2", ONE, 1, List.of("robot2")),
                new Offer("node-1", ONE, 1, List.of("robot2")));
        assertThat(InstallChoice.choose(tie).node()).as("one each, equal load: the lower name").isEqualTo("node-1");
        List<Offer> reversed = new java.util.ArrayList<>(tie);
        java.util.Collections.reverse(reversed);
        assertThat(InstallChoice.choose(reversed).node()).isEqualTo("node-1");
    }

    @Test
    void aNodeThatDoesNotSayOwnsNothing() {
        Offer silent = new Offer("a", ONE, 0, null);
        assertThat(silent.owns()).isEmpty();
        assertThat(InstallChoice.choose(List.of(silent, new Offer("b", ONE, 4, List.of("robot1")))).node())
                .isEqualTo("b");
    }

    @Test
    void noOfferNoChoice() {
        assertThat(InstallChoice.choose(List.of())).isNull();
        assertThat(InstallChoice.choose(List.of(new Offer("a", List.of(), 0)))).isNull();
    }
}
