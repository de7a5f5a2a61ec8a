package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;

import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;

/** Hands events to one behaviour: its own copy, in its own class, failures counted and logged once per type. */
class BehaviourCallerTest {

    public static class Moved extends BrainIoTEvent {
        public String robotId;
        public List<Integer> path = new ArrayList<>();
    }

    /** The behaviour's bundle's own copy of {@link Moved}. */
    public static class OwnMoved extends BrainIoTEvent {
        public String robotId;
        public List<Integer> path;
    }

    static final class Keeper<T extends BrainIoTEvent> implements SmartBehaviour<T> {
        final List<T> received = new ArrayList<>();

        @Override
        public void notify(T event) {
            received.add(event);
        }
    }

    /** Counts what it was given and given back. */
    static final class Handle implements BehaviourHandle {
        final Object behaviour;
        final AtomicInteger gets = new AtomicInteger();
        final AtomicInteger releases = new AtomicInteger();

        Handle(Object behaviour) {
            this.behaviour = behaviour;
        }

        @Override
        public Object get() {
            gets.incrementAndGet();
            return behaviour;
        }

        @Override
        public void release() {
            releases.incrementAndGet();
        }
    }

    final RecordingLogger log = new RecordingLogger();
    final EventTypeCounters counters = new EventTypeCounters(Moved.class.getName());

    private BehaviourCaller caller(Handle handle, boolean untyped, Function<String, Class<?>> classes) {
        return new BehaviourCaller(new ConsumerSpec(1, "keeper#1", "test.bundle", Set.of(Moved.class.getName()), null,
                false, untyped, handle, classes), log.logger);
    }

    static Moved moved(String robot) {
        Moved m = new Moved();
        m.robotId = robot;
        m.path.add(1);
        return m;
    }

    @Test
    void aSharedEventIsCopiedForTheBehaviourAndAnExclusiveOneIsHandedOver() {
        Keeper<Moved> keeper = new Keeper<>();
        Handle handle = new Handle(keeper);
        BehaviourCaller caller = caller(handle, false, name -> null);
        Moved shared = moved("robot1");
        caller.call(new Envelope(shared, counters, false));
        Moved exclusive = moved("robot2");
        caller.call(new Envelope(exclusive, counters, true));

        assertThat(keeper.received).hasSize(2);
        assertThat(keeper.received.get(0)).isNotSameAs(shared);
        assertThat(keeper.received.get(0).path).isNotSameAs(shared.path).isEqualTo(List.of(1));
        assertThat(keeper.received.get(1)).isSameAs(exclusive);
        assertThat(handle.gets).as("the behaviour object is fetched once").hasValue(1);
        assertThat(caller.delivered()).isEqualTo(2);
        assertThat(counters.delivered.sum()).isEqualTo(2);
    }

    @Test
    void aBehaviourWhoseBundleHasItsOwnClassReceivesAnInstanceOfIt() {
        Keeper<OwnMoved> keeper = new Keeper<>();
        BehaviourCaller caller = caller(new Handle(keeper), false,
                name -> name.equals(Moved.class.getName()) ? OwnMoved.class : null);
        caller.call(new Envelope(moved("robot1"), counters, true));
        caller.call(new Envelope(Map.of("robotId", "robot2", "path", List.of(4L)), counters, true));
        assertThat(keeper.received).extracting(e -> e.robotId).containsExactly("robot1", "robot2");
        assertThat(keeper.received).allSatisfy(e -> assertThat(e).isExactlyInstanceOf(OwnMoved.class));
        assertThat(keeper.received.get(1).path).containsExactly(4);
    }

    @Test
    void anUntypedBehaviourReceivesItsOwnMap() {
        List<Map<String, ?>> maps = new ArrayList<>();
        UntypedSmartBehaviour untyped = (type, properties) -> maps.add(properties);
        BehaviourCaller caller = caller(new Handle(untyped), true, name -> null);
        Moved event = moved("robot1");
        caller.call(new Envelope(event, counters, true));
        event.path.add(2); // the publisher's object changes after the copy: the behaviour's map does not
        assertThat(maps).singleElement().satisfies(m -> {
            assertThat(m.get("robotId")).isEqualTo("robot1");
            assertThat(m.get("path")).isEqualTo(List.of(1));
        });
    }

    @Test
    void aFailureIsCountedAndLoggedOncePerTypeAndTheBehaviourKeepsReceiving() {
        AtomicInteger calls = new AtomicInteger();
        SmartBehaviour<Moved> failing = e -> {
            if (calls.incrementAndGet() <= 3) {
                throw new IllegalStateException("boom " + calls.get());
            }
        };
        BehaviourCaller caller = caller(new Handle(failing), false, name -> null);
        for (int i = 0; i < 5; i++) {
            caller.call(new Envelope(moved("robot1"), counters, true));
        }
        assertThat(caller.failures()).isEqualTo(3);
        assertThat(caller.delivered()).isEqualTo(2);
        assertThat(counters.failed.sum()).isEqualTo(3);
        assertThat(log.count("error", "failed on an event of type")).isEqualTo(1);
    }

    @Test
    void aBehaviourThatIsGoneCountsAFailureAndIsGivenBackOnlyIfFetched() {
        Handle gone = new Handle(null);
        BehaviourCaller caller = caller(gone, false, name -> null);
        caller.call(new Envelope(moved("robot1"), counters, true));
        assertThat(caller.failures()).isEqualTo(1);
        caller.releaseBehaviour();
        assertThat(gone.releases).as("never obtained: nothing to give back").hasValue(0);

        Handle present = new Handle(new Keeper<Moved>());
        BehaviourCaller other = caller(present, false, name -> null);
        other.releaseBehaviour();
        assertThat(present.releases).as("never fetched").hasValue(0);
        other.call(new Envelope(moved("robot1"), counters, true));
        other.releaseBehaviour();
        other.releaseBehaviour();
        assertThat(present.releases).as("given back once").hasValue(1);
    }
}
