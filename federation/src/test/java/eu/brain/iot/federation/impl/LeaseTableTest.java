package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Predicate;

import org.junit.jupiter.api.Test;

/** The device lease policy on its own: who owns what, and when a device may move without two owners at once. */
class LeaseTableTest {

    static final long LEASE = 2_000;
    static final Set<String> FLEET = Set.of("robot1", "robot2", "robot3", "robot4", "door1");
    static final Set<String> SHARE1 = Set.of("robot1", "robot3", "door1");
    static final Set<String> SHARE2 = Set.of("robot2", "robot4");
    /** Every device at rest: each hand-over at once. */
    static final Predicate<String> ALL_AT_REST = d -> true;

    static LeaseTable.Lease lease(String node, Set<String> share, Set<String> owned, long at) {
        return new LeaseTable.Lease(node, share, owned, at, LEASE);
    }

    @Test
    void aNodeJustStartedTakesNothingForOneLeasePeriodThenItsShare() {
        LeaseTable t = new LeaseTable("node1", LEASE, 0, LEASE);
        t.heard(lease("node2", SHARE2, SHARE2, 0));
        assertThat(t.plan(LEASE, FLEET, SHARE1, Set.of(), ALL_AT_REST).take()).as("still listening").isEmpty();
        t.heard(lease("node2", SHARE2, SHARE2, LEASE));
        LeaseTable.Plan plan = t.plan(LEASE + 1, FLEET, SHARE1, Set.of(), ALL_AT_REST);
        assertThat(plan.take()).containsExactlyInAnyOrderElementsOf(SHARE1);
        assertThat(plan.release()).isEmpty();
    }

    @Test
    void theDevicesOfANodeWhoseLeaseLapsedGoToTheNodesAliveTheSameWayOnEach() {
        long now = 10 * LEASE;
        // three nodes; node3 shares nothing of the fleet here, node2 dies
        LeaseTable at1 = new LeaseTable("node1", LEASE, 0, LEASE);
        LeaseTable at3 = new LeaseTable("node3", LEASE, 0, LEASE);
        at1.heard(lease("node2", SHARE2, SHARE2, now - LEASE * 5 / 4)); // lapsed a quarter of a lease ago
        at1.heard(lease("node3", Set.of(), Set.of(), 0)); // heard all along
        at1.heard(lease("node3", Set.of(), Set.of(), now));
        at3.heard(lease("node2", SHARE2, SHARE2, now - LEASE * 5 / 4));
        at3.heard(lease("node1", SHARE1, SHARE1, 0));
        at3.heard(lease("node1", SHARE1, SHARE1, now));
        assertThat(at1.lapsed(now)).containsExactly("node2");

        Set<String> taken1 = at1.plan(now, FLEET, SHARE1, SHARE1, ALL_AT_REST).take();
        Set<String> taken3 = at3.plan(now, FLEET, Set.of(), Set.of(), ALL_AT_REST).take();
        Set<String> all = new TreeSet<>(taken1);
        all.addAll(taken3);
        assertThat(all).as("every device of node2, once").containsExactlyInAnyOrderElementsOf(SHARE2);
        assertThat(taken1.size() + taken3.size()).as("none taken twice").isEqualTo(SHARE2.size());
        for (String d : SHARE2) {
            assertThat(at1.owner(d, SHARE1, at1.alive(now))).as(d).isEqualTo(at3.owner(d, Set.of(), at3.alive(now)));
        }
    }

    @Test
    void whileTheHoldersLeaseStillListsADeviceItIsNotTaken() {
        long now = 10 * LEASE;
        LeaseTable t = new LeaseTable("node1", LEASE, 0, LEASE);
        // node2 holds node1's robot3 (taken while node1 was away) and has not let it go yet
        t.heard(lease("node2", SHARE2, Set.of("robot2", "robot4", "robot3"), 0));
        t.heard(lease("node2", SHARE2, Set.of("robot2", "robot4", "robot3"), now));
        LeaseTable.Plan plan = t.plan(now, FLEET, SHARE1, Set.of(), ALL_AT_REST);
        assertThat(plan.take()).containsExactlyInAnyOrder("robot1", "door1");

        LeaseTable at2 = new LeaseTable("node2", LEASE, 0, LEASE);
        at2.heard(lease("node1", SHARE1, Set.of("robot1", "door1"), now));
        assertThat(at2.plan(now, FLEET, SHARE2, Set.of("robot2", "robot4", "robot3"), ALL_AT_REST).release())
                .as("robot3 belongs to node1, alive again").containsExactly("robot3");

        t.heard(lease("node2", SHARE2, SHARE2, now + 1)); // its next lease, without robot3
        assertThat(t.plan(now + 1, FLEET, SHARE1, Set.of("robot1", "door1"), ALL_AT_REST).take())
                .as("a lease period first").isEmpty();
        t.heard(lease("node2", SHARE2, SHARE2, now + 1 + LEASE * 5 / 4));
        assertThat(t.plan(now + 1 + LEASE * 5 / 4, FLEET, SHARE1, Set.of("robot1", "door1"), ALL_AT_REST).take())
                .containsExactly("robot3");
    }

    @Test
    void twoNodesOwningOneDeviceLeaveItToTheLowerName() {
        long now = 10 * LEASE;
        LeaseTable at2 = new LeaseTable("node2", LEASE, 0, LEASE);
        at2.heard(lease("node1", SHARE1, Set.of("robot1", "robot3", "door1", "robot4"), now));
        // robot4 is node2's share, but node1 holds it as well (both took it in one renewal)
        assertThat(at2.plan(now, FLEET, SHARE2, SHARE2, d -> false).release()).as("at once, at rest or not")
                .containsExactly("robot4");
        LeaseTable at1 = new LeaseTable("node1", LEASE, 0, LEASE);
        at1.heard(lease("node2", SHARE2, SHARE2, now));
        assertThat(at1.plan(now, FLEET, SHARE1, Set.of("robot1", "robot3", "door1", "robot4"), ALL_AT_REST).release())
                .as("and node1 lets it go to its sharer").containsExactly("robot4");
    }

    @Test
    void devicesGoingBackToTheirNodeGoAtOnceAtRestAndTheOthersOneEveryHalfLeasePeriod() {
        long now = 10 * LEASE;
        LeaseTable at2 = new LeaseTable("node2", LEASE, 0, LEASE);
        at2.heard(lease("node1", SHARE1, Set.of(), now)); // node1 started again; node2 holds its share
        Set<String> owned = new TreeSet<>(FLEET);
        Predicate<String> atRest = "door1"::equals;
        assertThat(at2.plan(now, FLEET, SHARE2, owned, atRest).release()).as("door1 at rest, and one robot busy")
                .containsExactly("door1", "robot1");
        owned.removeAll(Set.of("door1", "robot1"));
        assertThat(at2.plan(now + LEASE / 4, FLEET, SHARE2, owned, atRest).release()).as("half a lease period first")
                .isEmpty();
        assertThat(at2.plan(now + LEASE / 4, FLEET, SHARE2, owned, ALL_AT_REST).release()).as("robot3 came to rest")
                .containsExactly("robot3");
        assertThat(at2.plan(now + LEASE / 2, FLEET, SHARE2, owned, atRest).release()).as("busy, its turn")
                .containsExactly("robot3");
        owned.remove("robot3");
        assertThat(at2.plan(now + LEASE, FLEET, SHARE2, owned, atRest).release()).as("its own share stays").isEmpty();
    }

    @Test
    void ownLeasesAreNotHeardAndANodeAloneOwnsTheWholeFleetOnceItsShareHoldersAreGone() {
        long now = 10 * LEASE;
        LeaseTable t = new LeaseTable("node1", LEASE, 0, LEASE);
        t.heard(lease("node1", SHARE1, FLEET, now));
        assertThat(t.alive(now)).isEmpty();
        t.heard(lease("node2", SHARE2, SHARE2, 0));
        assertThat(t.plan(now, FLEET, SHARE1, SHARE1, ALL_AT_REST).take())
                .containsExactlyInAnyOrder("robot2", "robot4");
        assertThat(List.copyOf(t.lapsed(now))).containsExactly("node2");
    }

    @Test
    void aDeviceNoNodeHasClaimedWaitsForTheJoinGraceSoThatItsNodeJoinsFirst() {
        long grace = 5 * LEASE;
        // node2 starts first: node1, whose share holds robot1, robot3 and door1, has not been heard yet
        LeaseTable at2 = new LeaseTable("node2", LEASE, 0, grace);
        assertThat(at2.plan(LEASE + 1, FLEET, SHARE2, Set.of(), ALL_AT_REST).take())
                .as("its own share after one lease period")
                .containsExactlyInAnyOrderElementsOf(SHARE2);
        assertThat(at2.plan(grace, FLEET, SHARE2, SHARE2, ALL_AT_REST).take())
                .as("no one else's during the grace").isEmpty();
        assertThat(at2.plan(grace + 1, FLEET, SHARE2, SHARE2, ALL_AT_REST).take()).as("node1 never came")
                .containsExactlyInAnyOrderElementsOf(SHARE1);

        // node1 joins within the grace: node2 never takes its share
        LeaseTable again = new LeaseTable("node2", LEASE, 0, grace);
        again.heard(lease("node1", SHARE1, Set.of(), grace)); // alive, still listening
        assertThat(again.plan(grace + 1, FLEET, SHARE2, SHARE2, ALL_AT_REST).take()).isEmpty();
    }

    @Test
    void theDevicesOfANodeHeardThatDiedAreTakenAtOnceEvenWithinTheJoinGrace() {
        long grace = 10 * LEASE;
        LeaseTable at2 = new LeaseTable("node2", LEASE, 0, grace);
        at2.heard(lease("node1", SHARE1, SHARE1, LEASE));
        long now = 3 * LEASE + 1; // node1's lease lapsed, well within the grace
        assertThat(at2.lapsed(now)).containsExactly("node1");
        assertThat(at2.plan(now, FLEET, SHARE2, SHARE2, ALL_AT_REST).take())
                .containsExactlyInAnyOrderElementsOf(SHARE1);
    }

    @Test
    void theDevicesOfALapsedHolderAreTakenALeasePeriodAndAQuarterAfterItsLastLease() {
        LeaseTable at1 = new LeaseTable("node1", LEASE, 0, LEASE);
        long last = 10 * LEASE; // node2's last lease; it may command until its next renewal, a quarter later
        at1.heard(lease("node2", SHARE2, SHARE2, last));
        assertThat(at1.lapsed(last + LEASE + 1)).containsExactly("node2");
        assertThat(at1.plan(last + LEASE + 1, FLEET, SHARE1, SHARE1, ALL_AT_REST).take())
                .as("lapsed, but its last command may be"
                + " less than a lease period ago").isEmpty();
        assertThat(at1.plan(last + LEASE * 5 / 4, FLEET, SHARE1, SHARE1, ALL_AT_REST).take())
                .containsExactlyInAnyOrderElementsOf(SHARE2);
    }

    @Test
    void aDeviceItsHolderReleasedIsTakenALeasePeriodAndAQuarterAfterTheRelease() {
        long now = 10 * LEASE;
        LeaseTable at2 = new LeaseTable("node2", LEASE, 0, LEASE);
        Set<String> held = Set.of("robot1", "robot3", "door1", "robot2", "robot4"); // node2's share taken when it died
        at2.heard(lease("node1", SHARE1, held, now));
        assertThat(at2.plan(now, FLEET, SHARE2, Set.of(), ALL_AT_REST).take()).as("node1 still holds it").isEmpty();
        at2.heard(lease("node1", SHARE1, SHARE1, now + 1)); // node1 released robot2 and robot4
        assertThat(at2.plan(now + 1, FLEET, SHARE2, Set.of(), ALL_AT_REST).take())
                .as("node1 may have commanded them just now")
                .isEmpty();
        at2.heard(lease("node1", SHARE1, SHARE1, now + LEASE * 5 / 4));
        assertThat(at2.plan(now + LEASE * 5 / 4, FLEET, SHARE2, Set.of(), ALL_AT_REST).take()).isEmpty();
        at2.heard(lease("node1", SHARE1, SHARE1, now + 1 + LEASE * 5 / 4));
        assertThat(at2.plan(now + 1 + LEASE * 5 / 4, FLEET, SHARE2, Set.of(), ALL_AT_REST).take())
                .as("a lease period and a quarter after the release").containsExactlyInAnyOrderElementsOf(SHARE2);
    }

    @Test
    void nothingIsTakenUntilEveryNodeAliveHasBeenHeardForALeasePeriod() {
        long now = 10 * LEASE;
        // node2 came back and hears node1 for the first time: node1 may have released robot2 just before
        LeaseTable at2 = new LeaseTable("node2", LEASE, now - LEASE - 1, LEASE);
        at2.heard(lease("node1", SHARE1, SHARE1, now));
        assertThat(at2.plan(now, FLEET, SHARE2, Set.of(), ALL_AT_REST).take()).isEmpty();
        at2.heard(lease("node1", SHARE1, SHARE1, now + LEASE));
        assertThat(at2.plan(now + LEASE, FLEET, SHARE2, Set.of(), ALL_AT_REST).take())
                .containsExactlyInAnyOrderElementsOf(SHARE2);
    }
}
