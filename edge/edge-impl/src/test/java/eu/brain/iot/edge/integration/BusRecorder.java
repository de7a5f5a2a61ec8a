package eu.brain.iot.edge.integration;

import static eu.brain.iot.edge.integration.EdgeTestSupport.DEADLINE;
import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;

import eu.brain.iot.edge.api.CartLifted;
import eu.brain.iot.edge.api.CartPlaced;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceRemoved;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.RobotEvent;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.robotsim.RobotSim;
import eu.brain.iot.robotsim.view.RobotView;

/**
 * A smart behaviour on the real bus that keeps every event the edge publishes (robot and door events, device
 * reachability and removal, command outcomes), in the order the bus delivered them. Register it before the edge is configured
 * so that it sees the first positions too.
 */
final class BusRecorder implements AutoCloseable {

    /** How often a wait for the bus looks again: a step waits for one poll of the edge, some 25-100 ms. */
    private static final Duration POLL = Duration.ofMillis(5);

    private final List<BrainIoTEvent> events = new CopyOnWriteArrayList<>();
    private final ServiceRegistration<?> registration;
    private int commands;

    BusRecorder(BundleContext context) {
        Hashtable<String, Object> properties = new Hashtable<>();
        properties.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, new String[] { RobotEvent.class.getName(),
                DoorStateChanged.class.getName(), DeviceUnreachable.class.getName(),
                DeviceRecovered.class.getName(), DeviceRemoved.class.getName(), CommandOutcome.class.getName() });
        SmartBehaviour<BrainIoTEvent> behaviour = events::add;
        registration = context.registerService(SmartBehaviour.class.getName(), behaviour, properties);
    }

    /** How many events arrived so far: a mark for {@link #since(int, Class)}. */
    int mark() {
        return events.size();
    }

    List<BrainIoTEvent> all() {
        return List.copyOf(events);
    }

    <E extends BrainIoTEvent> List<E> of(Class<E> type) {
        return since(0, type);
    }

    /** The events of this type that arrived after the mark. */
    <E extends BrainIoTEvent> List<E> since(int mark, Class<E> type) {
        // a copy first: a sub-list view of a CopyOnWriteArrayList fails once the bus adds an event to it
        List<BrainIoTEvent> all = List.copyOf(events);
        return all.subList(mark, all.size()).stream().filter(type::isInstance).map(type::cast).toList();
    }

    <E extends RobotEvent> List<E> of(Class<E> type, String robotId) {
        return of(type).stream().filter(e -> e.robotId.equals(robotId)).toList();
    }

    /** Where the bus last said the robot stands ("x,y"), or null. */
    String lastPosition(String robotId) {
        List<RobotPositionChanged> moves = of(RobotPositionChanged.class, robotId);
        return moves.isEmpty() ? null : at(moves.get(moves.size() - 1));
    }

    static String at(RobotPositionChanged e) {
        return e.x + "," + e.y;
    }

    static String at(RobotView r) {
        return r.x() + "," + r.y();
    }

    /** Publishes a command on the bus and returns its outcome, once the edge published it; it must be accepted. */
    CommandOutcome send(EventBus bus, EdgeCommand command) {
        command.commandId = "test-" + ++commands;
        bus.deliver(command);
        Predicate<CommandOutcome> mine = o -> o.commandId.equals(command.commandId);
        CommandOutcome outcome = await("the outcome of " + command.commandId).atMost(DEADLINE).pollInterval(POLL)
                .until(() -> of(CommandOutcome.class).stream().filter(mine).findFirst().orElse(null), o -> o != null);
        assertThat(outcome.accepted).as(outcome.reason).isTrue();
        return outcome;
    }

    /**
     * Steps the simulator one step at a time until {@code done}, and after each step waits until the bus has told
     * where the robot now stands and which cart it carries: no cell of its way, and no cart, can be missed. Returns the cells it stood on, in order.
     */
    List<String> follow(RobotSim sim, String robotId, BooleanSupplier done, int maxSteps) {
        List<String> route = new ArrayList<>(List.of(awaitSeen(sim, robotId)));
        for (int step = 0; step < maxSteps && !done.getAsBoolean(); step++) {
            sim.step(1);
            String now = awaitSeen(sim, robotId);
            if (!route.get(route.size() - 1).equals(now)) {
                route.add(now);
            }
        }
        assertThat(done.getAsBoolean()).as(robotId + " done within " + maxSteps + " steps: " + sim.robot(robotId))
                .isTrue();
        return route;
    }

    /**
     * Waits until the bus has told where the robot stands in the simulator now, and which cart it carries; returns
     * where ("x,y").
     */
    String awaitSeen(RobotSim sim, String robotId) {
        RobotView now = sim.robot(robotId);
        await(robotId + " at " + at(now) + " with cart " + now.cart() + " on the bus").atMost(DEADLINE)
                .pollInterval(POLL).until(() -> at(now).equals(lastPosition(robotId))
                        && Objects.equals(now.cart(), lastCart(robotId)));
        return at(now);
    }

    /** The cart the bus last said the robot lifted, null when it put it down (or never lifted one). */
    private String lastCart(String robotId) {
        String cart = null;
        for (RobotEvent e : of(RobotEvent.class, robotId)) {
            if (e instanceof CartLifted lifted) {
                cart = lifted.cartId;
            } else if (e instanceof CartPlaced) {
                cart = null;
            }
        }
        return cart;
    }

    @Override
    public void close() {
        registration.unregister();
    }
}
