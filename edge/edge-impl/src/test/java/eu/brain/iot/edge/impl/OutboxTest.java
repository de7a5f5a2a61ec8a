package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceReport;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The edge's outbox: never waits, keeps order, coalesces only robot positions and device reports, drops nothing
 * silently.
 */
class OutboxTest {

    final RecordingSink sink = new RecordingSink();
    final List<String> warnings = new ArrayList<>();
    final Outbox outbox = new Outbox(sink, new EdgeLog() {
        @Override
        public void warn(String message) {
            warnings.add(message);
        }

        @Override
        public void info(String message) {
        }

        @Override
        public void debug(String message) {
        }
    });

    static RobotPositionChanged position(String robot, int x, Integer previousX) {
        RobotPositionChanged e = new RobotPositionChanged();
        e.robotId = robot;
        e.x = x;
        e.y = 1;
        e.previousX = previousX;
        e.previousY = previousX == null ? null : 1;
        return e;
    }

    static MissionFinished finished(String robot, long mission) {
        MissionFinished e = new MissionFinished();
        e.robotId = robot;
        e.missionId = mission;
        return e;
    }

    @Test
    void eventsGoStraightThroughWhileTheBusTakesThem() {
        outbox.publish(position("robot1", 1, null));
        outbox.publish(finished("robot1", 7));
        assertThat(sink.events).hasSize(2);
        assertThat(outbox.isEmpty()).isTrue();
        assertThat(outbox.refusals()).isZero();
    }

    @Test
    void refusedEventsWaitInOrderAndAPositionReplacesTheSameRobotsWaitingOne() {
        sink.accepting = false;
        outbox.publish(position("robot1", 2, 1));
        ObstacleDetected obstacle = new ObstacleDetected();
        obstacle.robotId = "robot1";
        outbox.publish(obstacle);
        outbox.publish(position("robot1", 3, 2));
        CommandOutcome outcome = new CommandOutcome();
        outcome.commandId = "c1";
        outbox.publish(outcome);
        outbox.publish(position("robot2", 5, 4));
        outbox.flush(); // still refused: nothing leaves, nothing is lost
        assertThat(outbox.depth()).isEqualTo(4);
        assertThat(warnings).hasSize(1).first().asString().contains("bus:behaviours");

        sink.accepting = true;
        outbox.flush();
        assertThat(outbox.isEmpty()).isTrue();
        List<BrainIoTEvent> sent = sink.events;
        assertThat(sent).hasSize(4);
        assertThat(sent.get(0)).isSameAs(obstacle);
        RobotPositionChanged robot1 = (RobotPositionChanged) sent.get(1);
        assertThat(robot1.x).as("the newest position").isEqualTo(3);
        assertThat(robot1.previousX).as("where behaviours last heard robot1 was").isEqualTo(1);
        assertThat(sent.get(2)).isSameAs(outcome);
        assertThat(((RobotPositionChanged) sent.get(3)).robotId).isEqualTo("robot2");
        assertThat(outbox.coalesced()).isEqualTo(1);
    }

    static DeviceReport report(String node, String... ids) {
        DeviceReport r = new DeviceReport();
        r.node = node;
        r.devices = java.util.Arrays.stream(ids).map(id -> java.util.Map.<String, Object>of("id", id)).toList();
        return r;
    }

    @Test
    void aWaitingReportIsReplacedByANewerOneOfTheSameDevicesAtTheEndOfTheLine() {
        sink.accepting = false;
        DeviceReport first = report("node1", "robot1");
        outbox.publish(first);
        DeviceReport all = report("node1", "door1", "robot1", "robot2");
        outbox.publish(all);
        MissionFinished end = finished("robot1", 3);
        outbox.publish(end);
        DeviceReport newer = report("node1", "robot1");
        outbox.publish(newer);
        DeviceReport robot2 = report("node1", "robot2");
        outbox.publish(robot2);
        assertThat(outbox.depth()).isEqualTo(4);
        assertThat(outbox.reportsReplaced()).isEqualTo(1);

        sink.accepting = true;
        outbox.flush();
        assertThat(sink.events).containsExactly(all, end, newer, robot2);
        assertThat(outbox.coalesced()).as("robot positions").isZero();
    }

    @Test
    void missionEndsAndOtherEventsAreNeverCoalesced() {
        sink.accepting = false;
        for (int i = 0; i < 1_000; i++) {
            outbox.publish(finished("robot1", i));
            outbox.publish(position("robot1", i, i - 1));
        }
        assertThat(outbox.depth()).as("1,000 mission ends and robot1's newest position").isEqualTo(1_001);
        sink.accepting = true;
        outbox.flush();
        assertThat(sink.of(MissionFinished.class)).extracting(e -> e.missionId)
                .containsExactlyElementsOf(java.util.stream.LongStream.range(0, 1_000).boxed().toList());
        assertThat(sink.of(RobotPositionChanged.class)).singleElement().satisfies(p -> {
            assertThat(p.x).isEqualTo(999);
            assertThat(p.previousX).isEqualTo(-1);
        });
        assertThat(outbox.coalesced()).isEqualTo(999);
    }

    @Test
    void aNewEventQueuesBehindWaitingOnesEvenWhenTheBusWouldTakeIt() {
        sink.accepting = false;
        outbox.publish(finished("robot1", 1));
        sink.accepting = true;
        outbox.publish(finished("robot1", 2)); // must not overtake mission 1
        assertThat(sink.events).isEmpty();
        outbox.flush();
        assertThat(sink.of(MissionFinished.class)).extracting(e -> e.missionId).containsExactly(1L, 2L);
    }
}
