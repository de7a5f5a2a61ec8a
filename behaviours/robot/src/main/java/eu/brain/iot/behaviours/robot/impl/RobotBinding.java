package eu.brain.iot.behaviours.robot.impl;

import static eu.brain.iot.behaviours.warehouse.EventInputs.input;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Future;
import java.util.concurrent.RejectedExecutionException;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.behaviours.warehouse.BindingThread;
import eu.brain.iot.behaviours.warehouse.Cell;
import eu.brain.iot.behaviours.warehouse.EventInputs;
import eu.brain.iot.behaviours.warehouse.FleetView.DoorState;
import eu.brain.iot.behaviours.warehouse.Grid;
import eu.brain.iot.behaviours.warehouse.RobotNames;
import eu.brain.iot.behaviours.warehouse.RobotState;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.MissionFailed;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.ObstacleCleared;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The binding of the robot model to the edge, declared here and nowhere else: it consumes the edge's robot events
 * and fires the model's ports, by these rules (P is the robot's place in the model, s what the edge's device model
 * shows of it, e its errand; every poll period, and at once on an edge event about the robot):
 *
 * <pre>
 * P        condition (edge)                                               port event             data
 * START    s.detect != door, or the door ahead is closed; e has a goal    unloadLocation         area(s), 0
 *          or a cart waits for a robot and the wave is open (Errands)
 * UNLOAD   s moved to another cell                                        unloadToUnload         area(s), 0
 * UNLOAD   s stopped in front of a closed door (detect 2), or driving     fromUnloadObstacle     area(s), isDoor
 *          towards one within DOOR_LOOKAHEAD cells on its way
 * UNLOAD   s stopped behind a robot (detect 1) for patience polls         fromUnloadObstacle     area(s), isObstacle
 * STORAGE    (the same, on its way home)
 * UNLOAD   e goes for a cart, s stands on it, idle, carries none          fromUnloadObstacle     area(s), inFrontOfCart
 * UNLOAD   e goes home, s idle with a cart (its place lost): it carries   fromUnloadObstacle     area(s), inFrontOfCart
 * STORAGE    it to storage again, lifted anew in the model (Recovery)
 * UNLOAD   e carries to storage, s stands on its storage cell, idle       unloadToStorage        inStorage, 0
 * STORAGE  e goes home, s stands on its dock, idle                        storageToDocking       inDocking, 0
 * UNLOAD     (the same, when it went home through a resolved collision)
 * STORAGE  e goes home, s idle elsewhere (where it enters the docking     (none: RobotFleet.resume sends it on)
 *          area, or a go-to lost)
 * UNLOAD   idle before its errand's goal, or without one while a cart     (none: RobotFleet.resume sends the go-to)
 *          waits (a go-to cancelled, lost or never sent)
 * </pre>
 *
 * The rows that bring a robot back onto its errand (taken over carrying a cart, a cart on the floor, no storage cell
 * yet, idle before its goal or its dock, going home with its cart) are the recovery step ({@link Recovery}), looked
 * at before the normal moves.
 * A robot's model instance runs on the node that owns the robot ({@link RobotModelHost}): a port is fired by a
 * {@link RobotModelInput} naming that node (nodes without a host yet one at a time: {@link HostInstalls}), and the
 * robot's host answers with a {@link RobotModelReport} of its places,
 * data and the steps its extern functions asked of the fleet, which this binding applies ({@link ModelMirror});
 * until that report comes the binding leaves the robot alone, so that it never reads a place of the model without
 * the errand that goes with it. Robot-sim's {@code robotK} is component {@code Robot<(K-1)%3+1>} of group
 * {@code g<ceil(K/3)>} ({@link RobotNames}): the generated behaviour drives each robot by its group's copy of
 * Listing 4 (created by the group's first event, an {@code unloadLocation}: until then the host reports no places
 * and the binding reads START).
 * Command outcomes go to {@link RobotFleet#outcome}; mission ends clear its pending go-tos. A robot the edge cannot
 * reach gets no event until it answers again, then goes on where it was.
 * <p>
 * Immediate: its looks run on a timer, so it must not wait for a first event to be created (DS delays
 * components with a service until someone gets it). Its first inputs for the node's own robots may come before the
 * node's {@link RobotModelHost} registered (the components of a bundle start in no set order): the bus then holds them
 * for it.
 * <p>
 * In a fabric whose nodes share the fleet, only the instance that leads ({@link FleetLeadership}) looks, handles
 * events and fires ports, for every robot; the others leave everything as it is (their hosts run their node's model
 * instances).
 * <p>
 * Threads: {@link #notify} (the bus's delivery thread) makes of every event a {@link RobotInput} ({@link #INPUTS}) and
 * hands it to the fleet's thread ({@link RobotFleet#thread()}), which handles it ({@link InputHandler}), owns all of
 * this class's state (and the fleet's) and is the only one that evaluates the rules and publishes.
 */
@Component(service = SmartBehaviour.class, configurationPid = RobotConfig.PID, immediate = true)
@SmartBehaviourDefinition(consumed = { RobotPositionChanged.class, ObstacleDetected.class, ObstacleCleared.class,
        MissionFinished.class, MissionFailed.class, CommandOutcome.class, DeviceUnreachable.class,
        DeviceRecovered.class, RobotModelReport.class }, author = "BRAIN-IoT fabric", name = "Robot binding",
        description = "Binds the robot model's ports to the edge's robot events")
public final class RobotBinding implements SmartBehaviour<BrainIoTEvent> {

    /**
     * What each consumed event type (the list above: the two must name the same types, RobotInputTest) becomes for the
     * binding thread, made on the bus thread.
     */
    static final EventInputs<RobotInput> INPUTS = EventInputs.of(
            input(RobotPositionChanged.class, p -> new RobotInput.Moved(p.robotId, p.previousX == null)),
            input(ObstacleDetected.class, o -> new RobotInput.Obstacle(o.robotId, false)),
            input(ObstacleCleared.class, o -> new RobotInput.Obstacle(o.robotId, true)),
            input(MissionFinished.class,
                    m -> new RobotInput.MissionEnded(m.robotId, m.missionType, m.goalX, m.goalY, false, null)),
            input(MissionFailed.class,
                    m -> new RobotInput.MissionEnded(m.robotId, m.missionType, m.goalX, m.goalY, true, m.reason)),
            input(CommandOutcome.class, RobotInput.Outcome::new),
            input(DeviceUnreachable.class, u -> new RobotInput.Unreachable(u.deviceId, u.reason)),
            input(DeviceRecovered.class, r -> new RobotInput.Recovered(r.deviceId, r.deviceKind, r.downMillis)),
            input(RobotModelReport.class, RobotInput.Reported::new));

    private static final System.Logger LOG = System.getLogger(RobotBinding.class.getName());
    static final int IS_OBSTACLE = 4;
    static final int IS_DOOR = 5;
    static final int IN_FRONT_OF_CART = 6;
    /** Cells ahead on a robot's way within which a closed door is reported ({@link #closedDoorOnItsWay}). */
    static final int DOOR_LOOKAHEAD = 3;
    /** Looks after which a port event no host has answered is given up ({@link ModelMirror}). */
    static final int LOST_AFTER_LOOKS = 8;

    private final RobotFleet fleet;
    private final FleetLeadership leadership;
    private final EventBus bus;
    /** The robots' model instances as their hosts report them. */
    private final ModelMirror instances;
    /** Which nodes may be sent inputs now: those without a host yet, one at a time. */
    private final HostInstalls installs;
    private final long patienceNanos;
    /** The fleet's thread, which owns this binding's state too. */
    private final BindingThread thread;
    private final Future<?> looks;
    private volatile boolean closed;
    private final RobotInput.Handler handler = new InputHandler();
    /** Event types delivered that {@link #INPUTS} does not know (none: see {@link #notify}), each logged once. */
    private final Set<Class<?>> dropped = ConcurrentHashMap.newKeySet();

    // binding thread only
    private final Map<String, Long> blockedSince = new HashMap<>();
    private final Set<String> moved = new HashSet<>();
    /** Per robot: the model's state when the binding last published for it, and when. */
    private final Map<String, Published> published = new HashMap<>();
    private final StandingWatch standing = new StandingWatch();
    private final long pollNanos;

    /** The model's state (places and data) of a robot when an event was published for it. */
    private record Published(List<String> places, Map<String, Object> data, long atNanos) {
    }

    @Activate
    public RobotBinding(@Reference RobotFleet fleet, @Reference FleetLeadership leadership, @Reference EventBus bus,
            RobotConfig config) {
        this.fleet = fleet;
        this.leadership = leadership;
        this.bus = bus;
        this.thread = fleet.thread();
        this.pollNanos = thread.periodNanos();
        this.instances = new ModelMirror(leadership.instanceId(), pollNanos * LOST_AFTER_LOOKS, System.nanoTime());
        this.installs = new HostInstalls(leadership.nodeName());
        this.patienceNanos = pollNanos * Math.max(1, config.patience_polls());
        this.looks = thread.start(this::safeTick);
        LOG.log(System.Logger.Level.INFO, "robot binding: a look every {0} ms, patience {1} ms (wall time)",
                pollNanos / 1e6, patienceNanos / 1e6);
    }

    @Deactivate
    void deactivate() {
        closed = true;
        looks.cancel(false);
    }

    @Override
    public void notify(BrainIoTEvent event) {
        Class<?> type = event.getClass();
        RobotInput input = INPUTS.inputOf(event);
        if (input == null) {
            // cannot happen: the bus delivers only the consumed types (and their subtypes), the table's keys
            if (dropped.add(type)) {
                LOG.log(System.Logger.Level.WARNING, "robot binding: {0} is not a consumed event type: dropped",
                        type.getName());
            }
            return;
        }
        try {
            thread.execute(() -> {
                if (closed || !leadership.leads()) {
                    return;
                }
                try {
                    input.handle(handler);
                } catch (RuntimeException e) {
                    LOG.log(System.Logger.Level.WARNING, "robot binding: " + type.getSimpleName() + " not handled",
                            e);
                }
            });
        } catch (RejectedExecutionException e) {
            // the fleet is going away with this binding: nothing is driven any more
        }
    }

    /** The binding thread's treatment of each kind of input. */
    private final class InputHandler implements RobotInput.Handler {

        @Override
        public void outcome(RobotInput.Outcome o) {
            fleet.outcome(o.outcome());
        }

        @Override
        public void missionEnded(RobotInput.MissionEnded m) {
            if (!m.failed() || "cancelled".equals(m.reason())) {
                fleet.missionEnded(m.robot(), m.type(), m.goalX(), m.goalY());
            } else {
                fleet.missionFailed(m.robot(), m.type(), m.goalX(), m.goalY(), m.reason());
            }
            evaluate(m.robot());
        }

        @Override
        public void moved(RobotInput.Moved p) {
            if (p.appeared()) {
                fleet.handedOver(p.robot()); // on the node that polls it now: what the one before had is lost
                instances.handedOver(p.robot());
            }
            moved.add(p.robot());
            evaluate(p.robot());
        }

        @Override
        public void obstacle(RobotInput.Obstacle o) {
            if (o.cleared()) {
                blockedSince.remove(o.robot());
            }
            evaluate(o.robot());
        }

        @Override
        public void unreachable(RobotInput.Unreachable u) {
            LOG.log(System.Logger.Level.WARNING, "{0} is unreachable ({1}): its errand waits", u.device(), u.reason());
        }

        /**
         * Applies the steps; the robot is looked at again at the next look or edge event about it, not at once: a
         * robot whose model goes round a cycle of transitions (a door ahead still closed: UNLOAD, DOOR, START,
         * UNLOAD) then takes one step of it per look, not one per report.
         */
        @Override
        public void reported(RobotInput.Reported r) {
            String robot = r.report().robot;
            if (r.report().node != null) {
                installs.reported(r.report().node);
            }
            for (ModelStep step : instances.reported(r.report())) {
                switch (step.kind()) {
                    case MOVE_ON -> fleet.resume(robot, "its errand");
                    case STEP_ASIDE -> fleet.sideStep(robot, step.aside());
                    case LIFT -> fleet.lift(robot);
                    case PLACE -> fleet.place(robot);
                }
            }
        }

        @Override
        public void recovered(RobotInput.Recovered r) {
            if ("robot".equals(r.kind())) {
                LOG.log(System.Logger.Level.INFO, "{0} answers again after {1} ms: it goes on with its errand",
                        r.device(), r.downMillis());
                evaluate(r.device());
            }
        }
    }

    private void safeTick() {
        if (!leadership.leads()) {
            return; // another instance of the fabric drives the fleet (FleetLeadership)
        }
        try {
            fleet.expireUnanswered();
            fleet.trafficStep();
            for (RobotState s : fleet.view().robots()) {
                evaluate(s.id());
            }
            leadership.handover().share(fleet.errands()::handover); // for the instances standing by
        } catch (RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "robot binding: a look at the robots failed", e);
        }
    }

    /** Applies the rules of the table above to one robot. */
    private void evaluate(String robot) {
        int k = RobotNames.number(robot);
        if (k < 1) {
            return; // not a robot of the fleet's naming (robotK): no component of the model stands for it
        }
        Optional<RobotState> state = fleet.view().robot(robot);
        if (state.isEmpty() || !state.get().reachable()) {
            return;
        }
        RobotState s = state.get();
        fleet.adopt(s);
        long now = System.nanoTime();
        if (instances.awaiting(robot, now) || instances.reportDue(robot, now)) {
            return; // a port event's transitions and the steps they ask for, or a first report, are still to come
        }
        // an instance not reported yet (its node has no host yet: the first input has one installed) is in START
        Optional<ModelMirror.Instance> hosted = instances.of(robot).filter(h -> !h.places().isEmpty());
        List<String> places = hosted.map(ModelMirror.Instance::places).orElse(List.of("START"));
        Map<String, Object> data = hosted.map(ModelMirror.Instance::data).orElse(Map.of());
        Errands.Errand e = fleet.errands().of(robot);
        Instance in = new Instance(robot, places, data);
        standing.look(robot, s.cell(), e, places).ifPresent(line -> LOG.log(System.Logger.Level.WARNING, line));
        if (places.size() != 1) {
            return;
        }
        Published last = published.get(robot);
        if (last != null && last.places().equals(places) && last.data().equals(data)
                && now - last.atNanos() < 4 * pollNanos) {
            return; // the model has not taken the last event yet: never the same event twice
        }
        if (s.facesRobot() && !s.running()) {
            blockedSince.putIfAbsent(robot, now);
        } else {
            blockedSince.remove(robot);
        }
        double area = Math.max(Grid.DOCKING, Math.min(Grid.STORAGE,
                s.area() == Grid.CORRIDOR || s.area() == Grid.DOORWAY ? fleet.area(robot) : s.area()));
        switch (places.get(0)) {
            case "START" -> {
                boolean waitsAtOpeningDoor = s.facesDoor() && !doorAheadClosed(s);
                if (!waitsAtOpeningDoor && (e.goal() != null || e.leg() != Errands.Leg.NONE
                        || fleet.mayStart())) {
                    unloadLocation(in, area);
                }
            }
            case "UNLOAD" -> {
                if (obstacle(robot, s, in, area, now)) {
                    return;
                }
                Errands.Errand errand = e;
                Optional<Recovery.Step> fix = Recovery.inUnload(s, e, Boolean.TRUE.equals(data.get("carrying")),
                        () -> fleet.cartPutDown(s, errand) != null, fleet::workLeft, () -> fleet.placeUnseen(s));
                if (fix.isPresent()) {
                    recover(in, s, area, fix.get());
                } else if (e.leg() == Errands.Leg.TO_CART && s.cell().equals(e.cartCell()) && s.idle()
                        && !s.carrying()) {
                    fromUnloadObstacle(in, area, IN_FRONT_OF_CART);
                } else if (e.leg() == Errands.Leg.TO_STORAGE && s.cell().equals(e.drop()) && s.idle()
                        && s.carrying()) {
                    unloadToStorage(in);
                } else if (e.leg() == Errands.Leg.TO_DOCK && s.cell().equals(e.dock()) && s.idle()) {
                    fleet.errands().docked(robot);
                    storageToDocking(in);
                } else if (moved.remove(robot)) {
                    unloadToUnload(in, area);
                }
            }
            case "STORAGE" -> {
                if (obstacle(robot, s, in, area, now)) {
                    return;
                }
                Optional<Recovery.Step> fix = Recovery.carryingHome(s, e, () -> fleet.placeUnseen(s))
                        .or(() -> Recovery.homeward(s, e));
                if (fix.isPresent()) {
                    recover(in, s, area, fix.get()); // where it enters the docking area (DockingWay), a go-to lost
                } else if (e.leg() == Errands.Leg.TO_DOCK && s.cell().equals(e.dock()) && s.idle()) {
                    fleet.errands().docked(robot);
                    storageToDocking(in);
                }
            }
            case "DOCKING" -> {
                // a robot done with its carts (the model stays in DOCKING) that was sent out of the way goes home
                Optional<Recovery.Step> fix = Recovery.homeward(s, e);
                if (fix.isPresent()) {
                    recover(in, s, area, fix.get());
                } else if (e.leg() == Errands.Leg.TO_DOCK && s.cell().equals(e.dock()) && s.idle()) {
                    fleet.errands().docked(robot);
                }
            }
            default -> {
                // OBSTACLE, DOOR, CART, ROBOT: the model's own transitions, the door or the orchestrator
            }
        }
    }

    /** The recovery step's fix ({@link Recovery}), applied. */
    private void recover(Instance in, RobotState s, double area, Recovery.Step step) {
        switch (step.fix()) {
            case THROUGH_CART -> fromUnloadObstacle(in, area, IN_FRONT_OF_CART);
            case GO_ON -> fleet.resume(in.robot(), step.why());
            case CARRY_BACK -> {
                fleet.carryBack(s, step.why());
                fromUnloadObstacle(in, area, IN_FRONT_OF_CART);
            }
        }
    }

    /** A stop in front of a closed door, or behind a robot for longer than the patience: reported. */
    private boolean obstacle(String robot, RobotState s, Instance in, double area, long now) {
        if (s.facesDoor() && doorAheadClosed(s) || closedDoorOnItsWay(s)) {
            fromUnloadObstacle(in, area, IS_DOOR);
            return true;
        }
        Long since = blockedSince.get(robot);
        if (since != null && now - since >= patienceNanos) {
            blockedSince.remove(robot);
            LOG.log(System.Logger.Level.INFO, "{0} has been stopped behind a robot for {1} ms: reported", robot,
                    (now - since) / 1_000_000);
            fromUnloadObstacle(in, area, IS_OBSTACLE);
            return true;
        }
        return false;
    }

    /**
     * A robot driving towards a closed door reports it {@link #DOOR_LOOKAHEAD} cells before it, as its sensor would
     * see the door ahead on its way: the door opens (robot-sim: 4 steps) while the robot drives up to it, instead of
     * after it stopped in front of it with the robots behind it stopped too. Its way is the fleet's plan (a shortest
     * path, robots ignored; around the other carts when it carries one).
     */
    private boolean closedDoorOnItsWay(RobotState s) {
        if (!s.running() || s.goal() == null) {
            return false;
        }
        List<DoorState> closed = fleet.view().doors().stream().filter(d -> d.cell().distance(s.cell())
                <= DOOR_LOOKAHEAD && ("closed".equals(d.state()) || "closing".equals(d.state()))).toList();
        Optional<Grid> grid = closed.isEmpty() ? Optional.empty() : fleet.view().grid();
        if (grid.isEmpty()) {
            return false;
        }
        Set<Cell> carts = s.carrying() ? fleet.view().cartsOnTheFloor() : Set.of();
        List<Cell> way = grid.get().path(s.cell(), s.goal(), carts);
        if (way == null) {
            return false;
        }
        List<Cell> next = way.subList(0, Math.min(DOOR_LOOKAHEAD, way.size()));
        return closed.stream().anyMatch(d -> next.contains(d.cell()));
    }

    private boolean doorAheadClosed(RobotState s) {
        for (DoorState d : fleet.view().doors()) {
            if (d.cell().equals(s.ahead())) {
                return "closed".equals(d.state()) || "closing".equals(d.state());
            }
        }
        return false;
    }

    /**
     * Fires a port of the robot's model instance on its host, the robot's owner as this node's device model shows it,
     * remembering the state it was fired in.
     */
    private void fire(Instance in, ModelPort port, double position, int detect) {
        long now = System.nanoTime();
        String node = fleet.view().ownerNode(in.robot()).orElse(leadership.nodeName());
        if (!installs.mayFire(node, now)) {
            return; // its node may have no host yet: another node's is being installed first
        }
        published.put(in.robot(), new Published(in.places(), in.data(), now));
        bus.deliver(instances.input(in.robot(), node, port, position, detect, now));
    }

    /** A robot's model instance as the binding looked at it: its places and data as its host last reported them. */
    private record Instance(String robot, List<String> places, Map<String, Object> data) {
    }

    private void unloadLocation(Instance in, double position) {
        fire(in, ModelPort.UNLOAD_LOCATION, position, 0);
    }

    private void unloadToUnload(Instance in, double position) {
        fire(in, ModelPort.UNLOAD_TO_UNLOAD, position, 0);
    }

    private void fromUnloadObstacle(Instance in, double position, int detect) {
        fire(in, ModelPort.FROM_UNLOAD_OBSTACLE, position, detect);
    }

    private void unloadToStorage(Instance in) {
        fire(in, ModelPort.UNLOAD_TO_STORAGE, Grid.STORAGE, 0);
    }

    private void storageToDocking(Instance in) {
        fire(in, ModelPort.STORAGE_TO_DOCKING, Grid.DOCKING, 0);
    }
}
