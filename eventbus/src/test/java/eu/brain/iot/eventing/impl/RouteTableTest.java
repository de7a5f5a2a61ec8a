package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;

import eu.brain.iot.eventing.api.BrainIoTEvent;

/** Which behaviours take which events: by type, supertypes and interfaces, then filter; last resort apart. */
class RouteTableTest {

    public interface Movement {
    }

    public static class RobotEvent extends BrainIoTEvent {
        public String robotId;
    }

    public static class Moved extends RobotEvent implements Movement {
        public int x;
    }

    public static class DoorOpened extends BrainIoTEvent {
    }

    final RecordingLogger log = new RecordingLogger();
    final DeliveryPool pool = new DeliveryPool(new DeliveryPool.Settings(1, 0, TimeUnit.MILLISECONDS.toNanos(5),
            TimeUnit.SECONDS.toNanos(1)), log.logger); // never started: routing only
    final Map<String, EventTypeCounters> counters = new ConcurrentHashMap<>();
    final List<ConsumerChannel> channels = new ArrayList<>();
    long ids;

    private ConsumerChannel channel(String filter, boolean lastResort, String... consumed) {
        try {
            ConsumerChannel c = new ConsumerChannel(new ConsumerSpec(++ids, "b" + ids, "test", Set.of(consumed),
                    filter == null ? null : FrameworkUtil.createFilter(filter), lastResort, lastResort,
                    BehaviourHandle.of(new Object()), name -> null), 16, pool, log.logger);
            channels.add(c);
            return c;
        } catch (InvalidSyntaxException e) {
            throw new AssertionError(e);
        }
    }

    private EventTypeCounters counters(String type) {
        return counters.computeIfAbsent(type, EventTypeCounters::new);
    }

    @Test
    void aTypedEventReachesConsumersOfItsTypeItsSuperclassesAndItsInterfacesOnly() {
        ConsumerChannel exact = channel(null, false, Moved.class.getName());
        ConsumerChannel parent = channel(null, false, RobotEvent.class.getName());
        ConsumerChannel iface = channel(null, false, Movement.class.getName());
        ConsumerChannel all = channel(null, false, BrainIoTEvent.class.getName());
        ConsumerChannel other = channel(null, false, DoorOpened.class.getName());
        RouteTable table = new RouteTable(channels);

        RouteTable.Route route = table.routeFor(Moved.class, this::counters);
        assertThat(route.plain()).containsExactlyInAnyOrder(exact, parent, iface, all).doesNotContain(other);
        assertThat(route.filtered()).isEmpty();
        assertThat(route.counters().eventType).isEqualTo(Moved.class.getName());
        assertThat(route.typeNames()).startsWith(Moved.class.getName())
                .containsOnlyOnce(RobotEvent.class.getName(), Movement.class.getName(), BrainIoTEvent.class.getName(),
                        Cloneable.class.getName())
                .doesNotContain(Object.class.getName());
        assertThat(table.routeFor(DoorOpened.class, this::counters).plain()).containsExactlyInAnyOrder(other, all);
    }

    @Test
    void routesAreComputedOncePerTableAndANewTableSeesNewBehaviours() {
        channel(null, false, Moved.class.getName());
        RouteTable first = new RouteTable(channels);
        RouteTable.Route route = first.routeFor(Moved.class, this::counters);
        assertThat(first.routeFor(Moved.class, this::counters)).isSameAs(route);

        ConsumerChannel added = channel(null, false, RobotEvent.class.getName());
        assertThat(first.routeFor(Moved.class, this::counters).plain()).as("a table never changes")
                .doesNotContain(added);
        assertThat(new RouteTable(channels).routeFor(Moved.class, this::counters).plain()).contains(added);
    }

    @Test
    void anUntypedEventReachesConsumersOfExactlyItsName() {
        ConsumerChannel byName = channel(null, false, "com.example.Order");
        channel(null, false, BrainIoTEvent.class.getName());
        RouteTable table = new RouteTable(channels);
        assertThat(table.routeFor("com.example.Order", this::counters).plain()).containsExactly(byName);
        assertThat(table.routeFor("com.example.Order", this::counters).typeNames())
                .containsExactly("com.example.Order");
        assertThat(table.routeFor("com.example.Other", this::counters).plain()).isEmpty();
    }

    @Test
    void filteredConsumersGetOnlyTheEventsWhoseFieldsMatch() {
        ConsumerChannel plain = channel(null, false, Moved.class.getName());
        ConsumerChannel robot1 = channel("(robotId=robot1)", false, Moved.class.getName());
        ConsumerChannel farRight = channel("(x>=10)", false, RobotEvent.class.getName());
        RouteTable table = new RouteTable(channels);
        RouteTable.Route route = table.routeFor(Moved.class, this::counters);
        assertThat(route.plain()).containsExactly(plain);
        assertThat(route.filtered()).containsExactlyInAnyOrder(robot1, farRight);

        Moved near = new Moved();
        near.robotId = "robot1";
        near.x = 3;
        assertThat(route.targets(near)).containsExactlyInAnyOrder(plain, robot1);
        Moved far = new Moved();
        far.robotId = "robot2";
        far.x = 12;
        assertThat(route.targets(far)).containsExactlyInAnyOrder(plain, farRight);
        assertThat(route.targets(Map.of("robotId", "robot1", "x", 11))).as("an untyped event's fields")
                .containsExactlyInAnyOrder(plain, robot1, farRight);
    }

    @Test
    void consumersOfLastResortAreKeptApartAndTakeNoTypedRoute() {
        ConsumerChannel last = channel(null, true);
        ConsumerChannel typed = channel(null, false, Moved.class.getName());
        RouteTable table = new RouteTable(channels);
        assertThat(table.lastResort).containsExactly(last);
        assertThat(table.routeFor(Moved.class, this::counters).plain()).containsExactly(typed);
        assertThat(table.routeFor(DoorOpened.class, this::counters).plain()).isEmpty();
    }
}
