package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;

/** What {@code bus:publish} makes of its arguments, and a typed behaviour receiving such an untyped event. */
class EventArgumentsTest {

    public static class Position {
        public int x;
        public double y;
    }

    public static class Moved extends BrainIoTEvent {
        public String robotId;
        public int seq;
        public float speed;
        public boolean loaded;
        public Position at;
    }

    @Test
    void valuesAreTypedByTheirLookAndDottedKeysNest() {
        Map<String, Object> fields = EventArguments.parse("robotId=robot1", "seq=42", "big=12345678901",
                "speed=1.5", "loaded=true", "note=\"two words\"", "at.x=3", "at.y=-0.25", "plain=abc");
        assertThat(fields).containsEntry("robotId", "robot1").containsEntry("seq", 42)
                .containsEntry("big", 12_345_678_901L).containsEntry("speed", 1.5).containsEntry("loaded", true)
                .containsEntry("note", "two words").containsEntry("plain", "abc")
                .containsEntry("at", Map.of("x", 3, "y", -0.25));
    }

    @Test
    void badArgumentsSayWhichAndHow() {
        assertThatThrownBy(() -> EventArguments.parse("robotId=r", "oops")).hasMessageContaining("field 2 \"oops\"")
                .hasMessageContaining("key=value");
        assertThatThrownBy(() -> EventArguments.parse("seq=1", "seq=2")).hasMessageContaining("given twice");
        assertThatThrownBy(() -> EventArguments.parse("at=1", "at.x=2")).hasMessageContaining("already given");
    }

    @Test
    void aTypedBehaviourReceivesTheUntypedEventConvertedToItsClass() {
        AsyncEventBus bus = new AsyncEventBus("node", 100, 1_000, new DeliveryPool.Settings(1,
                TimeUnit.MICROSECONDS.toNanos(50), TimeUnit.MILLISECONDS.toNanos(5), TimeUnit.SECONDS.toNanos(1)),
                new RecordingLogger().logger);
        try {
            List<Moved> got = new CopyOnWriteArrayList<>();
            bus.addConsumer(new ConsumerSpec(1, "typed#1", "test.bundle", Set.of(Moved.class.getName()), null, false,
                    false, BehaviourHandle.of((SmartBehaviour<Moved>) got::add),
                    name -> name.equals(Moved.class.getName()) ? Moved.class : null));
            bus.deliver(Moved.class.getName(),
                    EventArguments.parse("robotId=robot1", "seq=7", "speed=2", "loaded=true", "at.x=3", "at.y=4.5"));
            await().atMost(Duration.ofSeconds(10)).until(() -> got.size() == 1);
            Moved moved = got.get(0);
            assertThat(moved.robotId).isEqualTo("robot1");
            assertThat(moved.seq).isEqualTo(7);
            assertThat(moved.speed).isEqualTo(2f);
            assertThat(moved.loaded).isTrue();
            assertThat(moved.at.x).isEqualTo(3);
            assertThat(moved.at.y).isEqualTo(4.5);
            assertThat(moved.sourceNode).isEqualTo("node");
            assertThat(moved.timestamp).isNotNull();
        } finally {
            bus.close();
        }
    }
}
