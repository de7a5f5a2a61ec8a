package eu.brain.iot.behaviours.robot.impl;

import java.util.Objects;
import java.util.UUID;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import org.osgi.service.component.ComponentContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * Whether this robot behaviour instance drives the fleet ({@link #leads}): on a node alone, always; in a fabric
 * whose nodes share the fleet, the instances beat ({@link RobotBehaviourAlive}, every {@value #BEAT_MILLIS} ms of
 * wall time) and the rule of {@link Leadership} picks one. The others' binding neither looks at the robots nor
 * publishes; their node's model instances go on being driven, through their host ({@link RobotModelHost}), by the
 * one that leads. The one that leads next continues the errands it shared ({@link ErrandHandover}) with the model
 * instances as their hosts report them.
 * <p>
 * Threads: the beat thread (one, its own) publishes and decides; the bus's thread records what it hears; both under
 * this object's lock. {@link #leads} reads a volatile.
 */
@Component(service = { SmartBehaviour.class, FleetLeadership.class }, immediate = true)
@SmartBehaviourDefinition(consumed = RobotBehaviourAlive.class, author = "BRAIN-IoT fabric",
        name = "Robot fleet leadership", description = "Picks the one robot behaviour instance of a fabric that drives"
                + " the fleet")
public final class FleetLeadership implements SmartBehaviour<RobotBehaviourAlive> {

    /** Wall time between two beats of an instance. */
    static final long BEAT_MILLIS = 500;
    /** An instance not heard for this long is gone (a lease period of the fabric's devices). */
    static final long ALIVE_MILLIS = 2_000;

    private static final System.Logger LOG = System.getLogger(FleetLeadership.class.getName());

    /**
     * The components that drive the fleet, enabled only while this instance leads. The model, its extern functions
     * and its host run on every node: each hosts the instances of the robots its node owns ({@link RobotModelHost}).
     */
    static final String[] DRIVING = { RobotBinding.class.getName() };

    private final EventBus bus;
    private final DeviceOwnership ownership;
    private final ComponentContext components;
    /** Whether the driving components are enabled; under the lock. */
    private boolean driving = true;
    private final Leadership rule;
    private final ScheduledExecutorService beats = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "robot-fleet-leadership");
        t.setDaemon(true);
        return t;
    });
    private volatile boolean leads;
    /** The id of the instance of the fabric (this one or another) known to drive the fleet, or null for none. */
    private volatile String leaderId;
    /** The errand table shared while this instance leads, and the leader's, heard while it stands by. */
    private final ErrandHandover handover = new ErrandHandover();
    /** The leader last logged; under the lock. */
    private Leadership.Instance lastLeader;

    @Activate
    public FleetLeadership(@Reference EventBus bus, @Reference DeviceOwnership ownership,
            ComponentContext components) {
        this.bus = bus;
        this.ownership = ownership;
        this.components = components;
        this.rule = new Leadership(new Leadership.Instance(ownership.nodeName(), UUID.randomUUID().toString(),
                System.currentTimeMillis()), ALIVE_MILLIS, System.nanoTime());
        this.leads = wholeFleetHere();
        drive(leads);
        beats.scheduleAtFixedRate(this::beat, 0, BEAT_MILLIS, TimeUnit.MILLISECONDS);
    }

    /**
     * Stops beating and says so ({@link RobotBehaviourAlive#leaving}), after the last beat: the other instances, and
     * the one the BMS starts here again, forget this one at once rather than one alive period later.
     */
    @Deactivate
    void deactivate() throws InterruptedException {
        beats.shutdownNow();
        if (!beats.awaitTermination(BEAT_MILLIS, TimeUnit.MILLISECONDS)) {
            LOG.log(System.Logger.Level.WARNING, "robot fleet leadership: the last beat did not end within {0} ms;"
                    + " the farewell goes out anyway", BEAT_MILLIS);
        }
        RobotBehaviourAlive farewell = beatOf(rule.self());
        farewell.leaving = true;
        try {
            bus.tryDeliver(farewell);
        } catch (RuntimeException e) { // the bus going away too (the node stops): the others wait an alive period
            LOG.log(System.Logger.Level.INFO, "robot fleet leadership: no farewell sent ({0}); the other instances"
                    + " take over when they stop hearing this one", e.toString());
        }
    }

    /** @return the errand table this instance shares while it leads, and inherits when it takes over */
    ErrandHandover handover() {
        return handover;
    }

    /** @return the name of this instance's node */
    String nodeName() {
        return ownership.nodeName();
    }

    /** @return this instance's id, new at each start, which its beats carry */
    String instanceId() {
        return rule.self().id();
    }

    /** @return the id of the instance of the fabric, this one or another, known to drive the fleet, or null */
    String leaderId() {
        return leaderId;
    }

    /** @return whether this instance drives the fleet now */
    public boolean leads() {
        return leads;
    }

    @Override
    public synchronized void notify(RobotBehaviourAlive beat) {
        if (beat.instance == null || beat.node == null) {
            return;
        }
        Leadership.Instance other = new Leadership.Instance(beat.node, beat.instance, beat.startedMillis);
        if (beat.leaving) {
            rule.left(other);
        } else {
            rule.heard(other, System.nanoTime());
        }
        if (beat.errands != null && !beat.errands.isEmpty() && !leads && !other.id().equals(rule.self().id())) {
            handover.heard(beat.errands);
        }
    }

    private RobotBehaviourAlive beatOf(Leadership.Instance self) {
        RobotBehaviourAlive alive = new RobotBehaviourAlive();
        alive.node = self.node();
        alive.instance = self.id();
        alive.startedMillis = self.startedMillis();
        alive.errands = leads ? handover.shared() : null;
        return alive;
    }

    private void beat() {
        try {
            bus.tryDeliver(beatOf(rule.self()));
            decide();
        } catch (RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "robot fleet leadership: a beat failed", e);
        }
    }

    private synchronized void decide() {
        Leadership.Instance leader = rule.leader(wholeFleetHere(), System.nanoTime());
        boolean now = leader == rule.self();
        if (!Objects.equals(leader, lastLeader)) {
            if (now) {
                LOG.log(System.Logger.Level.INFO, "robot fleet: this instance (node {0}) drives the fleet{1}",
                        rule.self().node(), lastLeader == null ? "" : "; the one on node " + lastLeader.node()
                                + " stopped or is not heard any more");
            } else if (leader != null) {
                LOG.log(System.Logger.Level.INFO, "robot fleet: the instance on node {0} drives the fleet; this one"
                        + " (node {1}) stands by and takes over if it stops", leader.node(), rule.self().node());
            }
            if (leads && !now && leader != null) {
                LOG.log(System.Logger.Level.WARNING, "robot fleet: an instance that started earlier (node {0}) is"
                        + " heard again: this one stops driving the fleet", leader.node());
            }
            lastLeader = leader;
        }
        if (leads && !now) {
            handover.standBy();
        }
        leads = now;
        leaderId = leader == null ? null : leader.id();
        drive(now);
    }

    /** Enables or disables the components that drive the fleet (SCR does it asynchronously). */
    private synchronized void drive(boolean on) {
        if (components == null || on == driving) {
            return;
        }
        for (String name : DRIVING) {
            if (on) {
                components.enableComponent(name);
            } else {
                components.disableComponent(name);
            }
        }
        driving = on;
    }

    private boolean wholeFleetHere() {
        var fleet = ownership.fleet();
        return !fleet.isEmpty() && ownership.owned().containsAll(fleet);
    }
}
