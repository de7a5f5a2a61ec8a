package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.federation.impl.InstallChoice.Offer;

/**
 * The rule that picks the node that installs: a candidate at all, then the most devices the event names owned, then
 * another node than the one that asked, then the lowest load, then the lowest name.
 */
class InstallChoiceTest {

    static final List<BehaviourCandidate> ONE = List.of(FakeInstaller.candidate("x", "T"));

    /** The choice of a node that is none of those offering (its own installer offered nothing). */
    private static Offer choose(List<Offer> offers) {
        return InstallChoice.choose(offers, "asker");
    }

    @Test
    void anotherNodeThanTheOneThatAskedWinsOverALowerLoadWhenNoNodeOwnsMoreOfTheNamedDevices() {
        List<Offer> offers = List.of(new Offer("a", ONE, 0), new Offer("b", ONE, 1), new Offer("c", ONE, 4));
        assertThat(InstallChoice.choose(offers, "a").node()).as("no device named: the lowest load of the others")
                .isEqualTo("b");
        List<Offer> oneEach = List.of(new Offer("a", ONE, 0, List.of("robot1")),
                new Offer("b", ONE, 3, List.of("robot2")));
        assertThat(InstallChoice.choose(oneEach, "a").node()).as("one each").isEqualTo("b");
    }

    @Test
    void theOwnerOfTheNamedDevicesWinsEvenWhenItAsked() {
        List<Offer> offers = List.of(new Offer("a", ONE, 3, List.of("robot1")), new Offer("b", ONE, 0));
        assertThat(InstallChoice.choose(offers, "a").node()).isEqualTo("a");
    }

    @Test
    void theNodeThatAskedInstallsWhenNoOtherOffers() {
        List<Offer> offers = List.of(new Offer("a", ONE, 5), new Offer("b", List.of(), 0));
        assertThat(InstallChoice.choose(offers, "a").node()).isEqualTo("a");
    }

    @Test
    void onlyNodesThatOfferACandidateCount() {
        Offer chosen = choose(List.of(new Offer("a", List.of(), 0), new Offer("b", null, 0),
                new Offer("c", ONE, 7)));
        assertThat(chosen.node()).isEqualTo("c");
    }

    @Test
    void theLowestLoadWins() {
        Offer chosen = choose(List.of(new Offer("a", ONE, 3), new Offer("b", ONE, 1),
                new Offer("c", ONE, 2)));
        assertThat(chosen.node()).isEqualTo("b");
    }

    @Test
    void onEqualLoadTheLowestNodeNameWinsWhateverTheOrderOfAnswers() {
        List<Offer> offers = List.of(new Offer("node-2", ONE, 1), new Offer("node-10", ONE, 1),
                new Offer("node-1", ONE, 1), new Offer("a", ONE, 2));
        assertThat(choose(offers).node()).isEqualTo("node-1");
        List<Offer> reversed = new java.util.ArrayList<>(offers);
        java.util.Collections.reverse(reversed);
        assertThat(choose(reversed).node()).isEqualTo("node-1");
    }

    @Test
    void theNodeThatOwnsTheDevicesTheEventNamesWinsOverALowerLoadAndALowerName() {
        Offer chosen = choose(List.of(new Offer("a", ONE, 0), new Offer("b", ONE, 5, List.of("robot2")),
                new Offer("c", ONE, 1)));
        assertThat(chosen.node()).isEqualTo("b");
    }

    @Test
    void owningWithoutACandidateCountsForNothing() {
        Offer chosen = choose(List.of(new Offer("a", ONE, 3), new Offer("b", List.of(), 0,
                List.of("robot2")), new Offer("c", null, 0, List.of("robot2"))));
        assertThat(chosen.node()).isEqualTo("a");
    }

    @Test
    void theNodeThatOwnsMoreOfTheNamedDevicesWinsThenLoadThenName() {
        assertThat(choose(List.of(new Offer("a", ONE, 0, List.of("door1")),
                new Offer("b", ONE, 9, List.of("door1", "robot2")))).node()).isEqualTo("b");
        assertThat(choose(List.of(new Offer("a", ONE, 2, List.of("robot2")),
                new Offer("b", ONE, 1, List.of("door1")))).node()).as("one each: the lower load").isEqualTo("b");
        List<Offer> tie = List.of(new Offer("node-2", ONE, 1, List.of("robot2")),
                new Offer("node-1", ONE, 1, List.of("robot2")));
        assertThat(choose(tie).node()).as("one each, equal load: the lower name").isEqualTo("node-1");
        List<Offer> reversed = new java.util.ArrayList<>(tie);
        java.util.Collections.reverse(reversed);
        assertThat(choose(reversed).node()).isEqualTo("node-1");
    }

    @Test
    void aNodeThatDoesNotSayOwnsNothing() {
        Offer silent = new Offer("a", ONE, 0, null);
        assertThat(silent.owns()).isEmpty();
        assertThat(choose(List.of(silent, new Offer("b", ONE, 4, List.of("robot1")))).node())
                .isEqualTo("b");
    }

    @Test
    void noOfferNoChoice() {
        assertThat(choose(List.of())).isNull();
        assertThat(choose(List.of(new Offer("a", List.of(), 0)))).isNull();
    }
}
