package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;

/**
 * The beats of an instance and its farewell, on a bus that records them, and what another instance makes of a
 * farewell: the instance the BMS starts again on the same node leads at once, whatever beat of the one before it
 * arrives after.
 */
class FleetLeadershipTest {

    private static final Duration DEADLINE = Duration.ofSeconds(10);

    /** A bus that records what is published. */
    static final class Recorded implements EventBus {
        final List<BrainIoTEvent> events = new CopyOnWriteArrayList<>();

        @Override
        public void deliver(BrainIoTEvent event) {
            events.add(event);
        }

        @Override
        public void deliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException();
        }

        @Override
        public boolean tryDeliver(BrainIoTEvent event) {
            events.add(event);
            return true;
        }

        @Override
        public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException();
        }

        List<RobotBehaviourAlive> beats() {
            return events.stream().filter(RobotBehaviourAlive.class::isInstance).map(RobotBehaviourAlive.class::cast)
                    .toList();
        }
    }

    /** A node's share of a fleet. */
    record Ownership(String nodeName, Set<String> owned, Set<String> fleet) implements DeviceOwnership {
        @Override
        public Set<String> share() {
            return owned;
        }

        @Override
        public boolean owns(String deviceId) {
            return owned.contains(deviceId);
        }

        @Override
        public Set<String> take(Set<String> deviceIds) {
            return Set.of();
        }

        @Override
        public Set<String> release(Set<String> deviceIds) {
            return Set.of();
        }
    }

    /** A node that owns the whole fleet of one robot. */
    private static Ownership wholeFleet() {
        return new Ownership("node1", Set.of("robot1"), Set.of("robot1"));
    }

    @Test
    void theLeadersBeatsCarryItsErrandTableAndAStandbyKeepsItForItsTakeover() throws Exception {
        Recorded bus = new Recorded();
        FleetLeadership leader = new FleetLeadership(bus, wholeFleet(), null);
        Recorded standbyBus = new Recorded();
        FleetLeadership standby = new FleetLeadership(standbyBus,
                new Ownership("node2", Set.of("robot1"), Set.of("robot1", "robot2")), null);
        try {
            leader.handover().share(() -> "robot1 1,1 1 TO_DOCK - - -\n");
            await().atMost(DEADLINE).until(() -> bus.beats().stream().anyMatch(b -> b.errands != null
                    && !b.errands.isEmpty()));
            RobotBehaviourAlive beat = bus.beats().stream().filter(b -> b.errands != null && !b.errands.isEmpty())
                    .findFirst().orElseThrow();
            assertThat(beat.errands).isEqualTo("robot1 1,1 1 TO_DOCK - - -\n");

            assertThat(standby.leads()).as("listening for a driver").isFalse();
            standby.notify(beat);
            assertThat(standby.handover().take(ErrandHandoverTest.MAP).errands().get("robot1").leg())
                    .isEqualTo(Errands.Leg.TO_DOCK);
            assertThat(standbyBus.beats()).as("a standby shares no table").isNotEmpty()
                    .allMatch(b -> b.errands == null);
        } finally {
            leader.deactivate();
            standby.deactivate();
        }
    }

    @Test
    void anInstanceThatStopsSaysSoAfterItsLastBeat() throws Exception {
        Recorded bus = new Recorded();
        FleetLeadership first = new FleetLeadership(bus, wholeFleet(), null);
        await().atMost(DEADLINE).until(() -> bus.beats().size() >= 2);
        first.deactivate();

        List<RobotBehaviourAlive> beats = bus.beats();
        RobotBehaviourAlive last = beats.get(beats.size() - 1);
        assertThat(last.leaving).as("the farewell is the last beat").isTrue();
        assertThat(beats.subList(0, beats.size() - 1)).noneMatch(b -> b.leaving);
        assertThat(beats).extracting(b -> b.instance).containsOnly(last.instance);
    }

    @Test
    void theInstanceStartedAgainOnTheNodeLeadsAtOnceThoughABeatOfTheOneBeforeArrivesAfterItsFarewell()
            throws Exception {
        Recorded before = new Recorded();
        FleetLeadership first = new FleetLeadership(before, wholeFleet(), null);
        await().atMost(DEADLINE).until(() -> before.beats().size() >= 2);
        first.deactivate();
        List<RobotBehaviourAlive> old = before.beats();

        Recorded now = new Recorded();
        FleetLeadership again = new FleetLeadership(now, wholeFleet(), null);
        try {
            // the older instance started earlier: heard alone, it would lead for an alive period (2 s)
            again.notify(old.get(old.size() - 1)); // the farewell
            again.notify(old.get(0)); // a beat of it delivered late
            int seen = now.beats().size();
            // a beat, its decision, and the next beat: the decision after a beat ends before the next beat
            await().atMost(DEADLINE).until(() -> now.beats().size() >= seen + 2);
            assertThat(again.leads()).as("decided within the old instance's alive period").isTrue();
        } finally {
            again.deactivate();
        }
    }
}
