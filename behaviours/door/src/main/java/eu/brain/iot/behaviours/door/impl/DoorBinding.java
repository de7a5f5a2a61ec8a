package eu.brain.iot.behaviours.door.impl;

import static eu.brain.iot.behaviours.warehouse.EventInputs.input;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.behaviours.door.DoorSmartBehaviour;
import eu.brain.iot.behaviours.events.DoorBehaviorClosed;
import eu.brain.iot.behaviours.warehouse.BindingThread;
import eu.brain.iot.behaviours.warehouse.EventInputs;
import eu.brain.iot.behaviours.warehouse.FleetView.DoorState;
import eu.brain.iot.behaviours.warehouse.RobotState;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The binding of the door model to the edge, declared here and nowhere else:
 *
 * <pre>
 * place  condition (edge)                                                   port event / command
 * OPEN   DoorStateChanged to closed (or the door is closed when looked at)  closed (DoorBehaviorClosed), to
 *                                                                           every group whose door model is OPEN
 * any    an open door with no robot within near.cells of it for             CloseDoorCommand
 *        close.after.polls looks in a row
 * </pre>
 *
 * Who closes the door: this binding, once no robot is near it for a while (3 s of warehouse time by default), so
 * a door stays open while robots come and go through it (every trip crosses the door: closing it between two
 * robots close behind each other would cost each an opening, 2 s) and is closed when the traffic stops. The model's
 * {@code closed} port follows the door's real state. The opening is the model's {@code open} extern
 * ({@link DoorExterns}). {@code DoorStateChanged} is this bundle's trigger: no other behaviour consumes it, so the
 * first door state the edge announces has the door behaviour installed on a bare node.
 * <p>
 * Immediate: its looks run on a timer, so it must not wait for a first event to be created (DS delays
 * components with a service until someone gets it).
 * <p>
 * Threads: {@link #notify} (the bus's delivery thread) makes of every event a {@link DoorInput} ({@link #INPUTS}) and
 * hands it to the binding's own thread, which handles it ({@link InputHandler}), owns the state and publishes.
 */
@Component(service = SmartBehaviour.class, configurationPid = DoorConfig.PID, immediate = true)
@SmartBehaviourDefinition(consumed = { DoorStateChanged.class, CommandOutcome.class }, author = "BRAIN-IoT fabric",
        name = "Door binding", description = "Binds the door model's ports to the edge's door events")
public final class DoorBinding implements SmartBehaviour<BrainIoTEvent> {

    /**
     * What each consumed event type (the list above: the two must name the same types, DoorInputTest) becomes for the
     * binding thread, made on the bus thread.
     */
    static final EventInputs<DoorInput> INPUTS = EventInputs.of(
            input(DoorStateChanged.class, d -> new DoorInput.StateChanged(d.doorId, d.state)),
            input(CommandOutcome.class, DoorInput.Outcome::new));

    private static final System.Logger LOG = System.getLogger(DoorBinding.class.getName());

    private final DoorControl control;
    private final EventBus bus;
    private final DoorSmartBehaviour model;
    private final int closeAfter;
    private final int near;
    private final BindingThread thread;
    private final DoorInput.Handler handler = new InputHandler();
    /** Event types delivered that {@link #INPUTS} does not know (none: see {@link #notify}), each logged once. */
    private final Set<Class<?>> dropped = ConcurrentHashMap.newKeySet();

    // binding thread only
    private final Map<String, Integer> quietLooks = new HashMap<>();

    @Activate
    public DoorBinding(@Reference DoorControl control, @Reference EventBus bus,
            @Reference(target = "(component.name=eu.brain.iot.behaviours.door.DoorSmartBehaviour)")
            SmartBehaviour<?> model, DoorConfig config) {
        this.control = control;
        this.bus = bus;
        this.model = (DoorSmartBehaviour) model;
        this.closeAfter = Math.max(1, config.close_after_polls());
        this.near = Math.max(1, config.near_cells());
        this.thread = new BindingThread("door-binding", config.speed(), config.poll_period_ms());
        thread.start(this::look);
    }

    @Deactivate
    void deactivate() {
        thread.close();
    }

    @Override
    public void notify(BrainIoTEvent event) {
        DoorInput input = INPUTS.inputOf(event);
        if (input == null) {
            // cannot happen: the bus delivers only the consumed types (and their subtypes), the table's keys
            if (dropped.add(event.getClass())) {
                LOG.log(System.Logger.Level.WARNING, "door binding: {0} is not a consumed event type: dropped",
                        event.getClass().getName());
            }
            return;
        }
        thread.execute(() -> input.handle(handler));
    }

    /** The binding thread's treatment of each kind of input. */
    private final class InputHandler implements DoorInput.Handler {

        @Override
        public void outcome(DoorInput.Outcome o) {
            control.outcome(o.outcome());
        }

        @Override
        public void stateChanged(DoorInput.StateChanged d) {
            LOG.log(System.Logger.Level.DEBUG, "{0} is {1}", d.door(), d.state());
            closedWhenOpenInModel("closed".equals(d.state()));
        }
    }

    /**
     * The real door is closed: every group whose door model is OPEN follows ({@code closed}, to that group). Each
     * group has its own {@code DoorInstance} (bip/README, "Groups"), all standing for the one real door.
     */
    private void closedWhenOpenInModel(boolean closed) {
        if (!closed) {
            return;
        }
        for (String group : model.groups()) {
            List<String> places = model.placesOf(group, "DoorInstance");
            if (places != null && places.contains("OPEN")) {
                DoorBehaviorClosed e = new DoorBehaviorClosed();
                e.group = group.isEmpty() ? null : group;
                e.component = "DoorInstance";
                bus.deliver(e);
            }
        }
    }

    private void look() {
        try {
            List<DoorState> doors = control.view().doors();
            List<RobotState> robots = control.view().robots();
            boolean allClosed = !doors.isEmpty();
            for (DoorState d : doors) {
                allClosed &= "closed".equals(d.state());
                if (!"open".equals(d.state())) {
                    quietLooks.remove(d.id());
                    continue;
                }
                boolean someoneNear = robots.stream().anyMatch(r -> r.cell().distance(d.cell()) <= near
                        || r.facesDoor() && r.ahead().equals(d.cell()));
                int quiet = someoneNear ? 0 : quietLooks.getOrDefault(d.id(), 0) + 1;
                quietLooks.put(d.id(), quiet);
                if (quiet == closeAfter) {
                    control.close(d.id(), "no robot near it for " + quiet + " polls");
                }
            }
            closedWhenOpenInModel(allClosed);
        } catch (RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "door binding: a look at the doors failed", e);
        }
    }
}
