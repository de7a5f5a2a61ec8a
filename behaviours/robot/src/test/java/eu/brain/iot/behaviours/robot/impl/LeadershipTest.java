package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** One robot behaviour instance of a fabric drives the fleet: the eldest alive; a newcomer listens first. */
class LeadershipTest {

    private static final long MS = 1_000_000L;
    private static final Leadership.Instance A = new Leadership.Instance("node1", "a", 1_000);
    private static final Leadership.Instance B = new Leadership.Instance("node2", "b", 2_000);

    @Test
    void aNodeWithTheWholeFleetLeadsAtOnce() {
        Leadership alone = new Leadership(A, 2_000, 0);
        assertThat(alone.leader(true, 0)).isEqualTo(A);
    }

    @Test
    void onASharedFleetANewInstanceListensForSomeAlivePeriodsThenLeadsWhenNobodyElseIsHeard() {
        Leadership b = new Leadership(B, 2_000, 0);
        long listen = Leadership.LISTEN_PERIODS * 2_000L;
        assertThat(b.leader(false, 2_001 * MS)).as("one alive period").isNull();
        assertThat(b.leader(false, (listen - 1) * MS)).isNull();
        assertThat(b.leader(false, (listen + 1) * MS)).isEqualTo(B);
    }

    @Test
    void theEldestInstanceHeardLeadsAndTheYoungerStandsBy() {
        Leadership a = new Leadership(A, 2_000, 0);
        Leadership b = new Leadership(B, 2_000, 0);
        a.heard(B, 100 * MS);
        b.heard(A, 100 * MS);

        assertThat(b.leader(false, 200 * MS)).isEqualTo(A);
        assertThat(a.leader(false, 200 * MS)).as("an elder one may still be to be heard").isNull();
        a.heard(B, 1_900 * MS);
        assertThat(a.leader(false, 2_001 * MS)).isEqualTo(A);
    }

    @Test
    void whenTheLeaderIsNotHeardForAnAlivePeriodTheNextTakesOver() {
        Leadership b = new Leadership(B, 2_000, 0);
        b.heard(A, 100 * MS);
        assertThat(b.leader(false, 2_000 * MS)).isEqualTo(A);

        assertThat(b.leader(false, 2_101 * MS)).isEqualTo(B);
    }

    @Test
    void aYoungerInstanceHeardDoesNotTakeTheLeadAndItsOwnBeatsAreIgnored() {
        Leadership a = new Leadership(A, 2_000, 0);
        a.heard(A, 0);
        a.heard(B, 0);
        a.heard(B, 2_000 * MS);
        assertThat(a.leader(false, 2_010 * MS)).isEqualTo(A);
    }

    @Test
    void equalStartsAreDecidedByTheInstanceId() {
        Leadership.Instance c = new Leadership.Instance("node3", "c", 1_000);
        Leadership l = new Leadership(c, 2_000, 0);
        l.heard(A, 0);
        assertThat(l.leader(false, 10 * MS)).isEqualTo(A);
    }

    @Test
    void anInstanceThatSaysItLeavesIsForgottenAtOnceAndItsLaterBeatsAreIgnored() {
        Leadership b = new Leadership(B, 2_000, 0);
        b.heard(A, 100 * MS);
        assertThat(b.leader(true, 200 * MS)).as("the eldest leads, even on a node with the whole fleet").isEqualTo(A);

        b.left(A);
        assertThat(b.leader(true, 300 * MS)).as("at once, not an alive period later").isEqualTo(B);
        b.heard(A, 400 * MS); // a beat sent before the farewell, delivered after it
        assertThat(b.leader(true, 500 * MS)).isEqualTo(B);
    }

    @Test
    void aFarewellAloneDoesNotEndTheListeningOfANewInstanceOnASharedFleet() {
        Leadership b = new Leadership(B, 2_000, 0);
        b.left(A);
        b.heard(A, 10 * MS);
        // the instance that drives the fleet may still be to be heard: a farewell says nothing of it
        assertThat(b.leader(false, 20 * MS)).isNull();
        assertThat(b.leader(true, 20 * MS)).as("a node with the whole fleet").isEqualTo(B);
    }

    @Test
    void itsOwnFarewellIsIgnored() {
        Leadership a = new Leadership(A, 2_000, 0);
        a.left(A);
        assertThat(a.leader(true, 10 * MS)).isEqualTo(A);
    }
}
