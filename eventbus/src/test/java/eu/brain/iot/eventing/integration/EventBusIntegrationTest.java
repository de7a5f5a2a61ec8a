package eu.brain.iot.eventing.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.monitoring.api.ConsumerStatistics;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/** The bus's delivery guarantees, checked on the real bundle in a real framework. */
class EventBusIntegrationTest {

    static final Duration DEADLINE = Duration.ofSeconds(10);

    @InjectBundleContext
    BundleContext context;

    @InjectService(timeout = 5000)
    EventBus bus;

    @InjectService(timeout = 5000)
    EventBusStatistics stats;

    BusTestSupport behaviours;
    int baseline;

    @BeforeEach
    void setUp() {
        behaviours = new BusTestSupport(context);
        baseline = stats.consumers().size(); // behaviours other tests' bundles keep registered
    }

    private void awaitConsumers(int count) {
        await().atMost(DEADLINE).untilAsserted(() -> assertThat(stats.consumers()).hasSize(baseline + count));
    }

    private EventTypeStatistics statsOf(Class<?> type) {
        return stats.eventTypes().stream().filter(s -> s.eventType.equals(type.getName())).findFirst()
                .orElseGet(EventTypeStatistics::new);
    }

    @Test
    void eachConsumerSeesEveryPublisherEventsInOrder() throws Exception {
        int publishers = 4;
        int perPublisher = 5_000;
        List<Map<String, Long>> lastSeqs = new ArrayList<>();
        List<AtomicInteger> outOfOrder = new ArrayList<>();
        List<AtomicInteger> received = new ArrayList<>();
        for (int c = 0; c < 3; c++) {
            Map<String, Long> last = new ConcurrentHashMap<>();
            AtomicInteger bad = new AtomicInteger();
            AtomicInteger count = new AtomicInteger();
            lastSeqs.add(last);
            outOfOrder.add(bad);
            received.add(count);
            behaviours.typed((SmartBehaviour<PositionEvent>) e -> {
                Long previous = last.put(e.robotId, e.seq);
                if (previous != null && previous + 1 != e.seq) {
                    bad.incrementAndGet();
                }
                count.incrementAndGet();
            }, null, PositionEvent.class);
        }
        awaitConsumers(3);

        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < publishers; p++) {
            String robot = "publisher" + p;
            threads.add(new Thread(() -> {
                PositionEvent event = new PositionEvent(robot, 0, 0, 0);
                for (int i = 0; i < perPublisher; i++) {
                    event.seq = i; // the publisher reuses its object: the bus must have copied it
                    bus.deliver(event);
                }
            }));
        }
        threads.forEach(Thread::start);
        for (Thread t : threads) {
            t.join();
        }
        await().atMost(DEADLINE).until(() -> received.stream().allMatch(r -> r.get() == publishers * perPublisher));
        assertThat(outOfOrder).allSatisfy(bad -> assertThat(bad.get()).isZero());
        assertThat(lastSeqs).allSatisfy(last -> assertThat(last).hasSize(publishers)
                .allSatisfy((robot, seq) -> assertThat(seq).isEqualTo(perPublisher - 1L)));
    }

    @Test
    void aBlockedConsumerDoesNotDelayTheOthers() throws Exception {
        GatedBehaviour blocked = new GatedBehaviour();
        behaviours.typed(blocked, null, PositionEvent.class);
        Recorder fast = new Recorder();
        behaviours.typed(fast, null, PositionEvent.class);
        awaitConsumers(2);

        for (int i = 0; i < 1_000; i++) {
            bus.deliver(new PositionEvent("r1", i, 0, i));
        }
        // Every event reaches the fast consumer while the other one is still stuck in its first event.
        await().atMost(DEADLINE).until(() -> fast.events.size() == 1_000);
        assertThat(blocked.received()).isEqualTo(1);
        assertThat(stats.consumers()).anySatisfy(c -> assertThat(c.queueDepth).isGreaterThanOrEqualTo(998));

        blocked.open();
        await().atMost(DEADLINE).until(() -> blocked.received() == 1_000);
    }

    @Test
    void aThrowingConsumerIsCountedAndKeepsReceiving() {
        AtomicInteger calls = new AtomicInteger();
        behaviours.typed((SmartBehaviour<PositionEvent>) e -> {
            calls.incrementAndGet();
            throw new IllegalStateException("behaviour bug on " + e.seq);
        }, null, PositionEvent.class);
        Recorder healthy = new Recorder();
        behaviours.typed(healthy, null, PositionEvent.class);
        awaitConsumers(2);
        long failedBefore = statsOf(PositionEvent.class).failed;

        for (int i = 0; i < 100; i++) {
            bus.deliver(new PositionEvent("r1", i, 0, i));
        }
        await().atMost(DEADLINE).until(() -> calls.get() == 100 && healthy.events.size() == 100);
        await().atMost(DEADLINE).until(() -> statsOf(PositionEvent.class).failed - failedBefore == 100);
        assertThat(stats.consumers()).anySatisfy(c -> assertThat(c.failures).isEqualTo(100));
    }

    @Test
    void filtersSelectEventsByTheirFields() {
        Recorder robot1 = new Recorder();
        Recorder farRight = new Recorder();
        behaviours.typed(robot1, "(robotId=robot1)", PositionEvent.class);
        behaviours.typed(farRight, "(&(x>=10)(!(robotId=robot1)))", PositionEvent.class);
        awaitConsumers(2);

        bus.deliver(new PositionEvent("robot1", 12, 0, 1));
        bus.deliver(new PositionEvent("robot2", 3, 0, 2));
        bus.deliver(new PositionEvent("robot2", 11, 0, 3));
        bus.deliver(new PositionEvent("robot1", 1, 0, 4));

        await().atMost(DEADLINE).until(() -> robot1.events.size() == 2 && farRight.events.size() == 1);
        assertThat(robot1.events).extracting(e -> ((PositionEvent) e).seq).containsExactly(1L, 4L);
        assertThat(farRight.events).extracting(e -> ((PositionEvent) e).seq).containsExactly(3L);
    }

    @Test
    void consumersOfASupertypeOrInterfaceReceiveSubtypes() {
        Recorder ofSuperclass = new Recorder();
        Recorder ofInterface = new Recorder();
        Recorder ofEverything = new Recorder();
        Recorder ofSubtypeOnly = new Recorder();
        behaviours.typed(ofSuperclass, null, PositionEvent.class);
        behaviours.typed(ofInterface, null, Robotic.class);
        behaviours.typed(ofEverything, null, BrainIoTEvent.class);
        behaviours.typed(ofSubtypeOnly, null, MovedEvent.class);
        awaitConsumers(4);

        MovedEvent moved = new MovedEvent();
        moved.robotId = "robot3";
        moved.from = "docking";
        bus.deliver(moved);
        bus.deliver(new PositionEvent("robot3", 1, 1, 1));

        await().atMost(DEADLINE).until(() -> ofSuperclass.events.size() == 2 && ofEverything.events.size() == 2
                && ofInterface.events.size() == 1 && ofSubtypeOnly.events.size() == 1);
        assertThat(ofInterface.events.get(0)).isInstanceOf(MovedEvent.class);
        assertThat(((MovedEvent) ofSubtypeOnly.events.get(0)).from).isEqualTo("docking");
    }

    @Test
    void everyConsumerGetsItsOwnSnapshotWithSourceAndTimestamp() {
        List<PositionEvent> seen = new ArrayList<>();
        CountDownLatch both = new CountDownLatch(2);
        SmartBehaviour<PositionEvent> mutating = e -> {
            synchronized (seen) {
                seen.add(e);
            }
            e.x = -1; // as the paper's Listing 3 does with what it receives
            e.path[0] = -1;
            both.countDown();
        };
        behaviours.typed(mutating, null, PositionEvent.class);
        behaviours.typed(mutating, null, PositionEvent.class);
        awaitConsumers(2);

        PositionEvent published = new PositionEvent("robot1", 5, 6, 7);
        published.path = new int[] { 1, 2, 3 };
        bus.deliver(published);
        published.y = 99; // after deliver: nobody may see it
        published.path[1] = 99;

        await().atMost(DEADLINE).until(() -> both.getCount() == 0);
        assertThat(seen.get(0)).isNotSameAs(seen.get(1)).isNotSameAs(published);
        assertThat(seen.get(0).path).isNotSameAs(seen.get(1).path);
        assertThat(seen).allSatisfy(e -> {
            assertThat(e.y).isEqualTo(6);
            assertThat(e.path[1]).isEqualTo(2);
            assertThat(e.sourceNode).isEqualTo(context.getProperty(Constants.FRAMEWORK_UUID));
            assertThat(e.timestamp).isNotNull();
        });
        assertThat(published.x).isEqualTo(5);
        assertThat(published.sourceNode).isNull();
    }

    @Test
    void untypedConsumersGetMapsAndTypedConsumersGetUntypedEvents() {
        Recorder untyped = new Recorder();
        behaviours.untyped(untyped, PositionEvent.class.getName());
        Recorder typed = new Recorder();
        behaviours.typed(typed, null, PositionEvent.class);
        awaitConsumers(2);

        PositionEvent typedEvent = new PositionEvent("robot1", 1, 2, 3);
        typedEvent.path = new int[] { 4, 5 };
        bus.deliver(typedEvent);
        Map<String, Object> fields = new HashMap<>();
        fields.put("robotId", "robot2");
        fields.put("x", 7);
        fields.put("y", "8"); // converted to the field's type
        fields.put("seq", 9L);
        bus.deliver(PositionEvent.class.getName(), fields);

        await().atMost(DEADLINE).until(() -> untyped.maps.size() == 2 && typed.events.size() == 2);
        assertThat(untyped.types).containsOnly(PositionEvent.class.getName());
        assertThat(untyped.maps.get(0)).containsEntry("robotId", "robot1").containsEntry("x", 1)
                .containsEntry("path", List.of(4, 5)).containsKey("timestamp");
        assertThat(untyped.maps.get(1)).containsEntry("robotId", "robot2");
        PositionEvent converted = (PositionEvent) typed.events.get(1);
        assertThat(converted.robotId).isEqualTo("robot2");
        assertThat(converted.x).isEqualTo(7);
        assertThat(converted.y).isEqualTo(8);
        assertThat(converted.seq).isEqualTo(9L);
        assertThat(converted.sourceNode).isEqualTo(context.getProperty(Constants.FRAMEWORK_UUID));
    }

    @Test
    void consumersOfLastResortGetOnlyEventsNobodyElseConsumes() {
        Recorder lastResort = new Recorder();
        behaviours.lastResort(lastResort);
        Recorder positions = new Recorder();
        behaviours.typed(positions, "(robotId=robot1)", PositionEvent.class);
        awaitConsumers(2);

        bus.deliver(new PositionEvent("robot1", 0, 0, 1)); // consumed
        bus.deliver(new PositionEvent("robot2", 0, 0, 2)); // filtered out everywhere: unhandled
        Map<String, Object> door = new HashMap<>();
        door.put("doorId", "door1");
        bus.deliver("eu.brain.iot.example.DoorOpened", door); // no consumer at all

        await().atMost(DEADLINE).until(() -> lastResort.maps.size() == 2 && positions.events.size() == 1);
        assertThat(lastResort.types).containsExactly(PositionEvent.class.getName(), "eu.brain.iot.example.DoorOpened");
        assertThat(lastResort.maps.get(0)).containsEntry("robotId", "robot2");
        assertThat(lastResort.maps.get(1)).containsEntry("doorId", "door1");
    }

    @Test
    void statisticsListBehavioursAndCounters() {
        Recorder recorder = new Recorder();
        behaviours.typed(recorder, "(robotId=robot9)", PositionEvent.class);
        awaitConsumers(1);
        long before = statsOf(PositionEvent.class).delivered;
        bus.deliver(new PositionEvent("robot9", 0, 0, 1));
        await().atMost(DEADLINE).until(() -> statsOf(PositionEvent.class).delivered == before + 1);
        ConsumerStatistics consumer = stats.consumers().stream().filter(c -> c.filter.equals("(robotId=robot9)"))
                .findFirst().orElseThrow();
        assertThat(consumer.consumed).containsExactly(PositionEvent.class.getName());
        assertThat(consumer.filter).isEqualTo("(robotId=robot9)");
        assertThat(consumer.bundle).isEqualTo(context.getBundle().getSymbolicName());
        assertThat(consumer.delivered).isEqualTo(1);
    }
}
