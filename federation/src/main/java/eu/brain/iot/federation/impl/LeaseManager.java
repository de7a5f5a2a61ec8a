package eu.brain.iot.federation.impl;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicyOption;

import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.federation.api.DeviceLease;

/**
 * This node's device leases ({@link LeaseTable} is the policy): every {@code renew.ms} it applies the table (releases
 * what belongs to another node, takes what belongs to it and nobody holds), then publishes its lease, a
 * {@link DeviceLease} that the fabric routes to every other node's lease manager (each consumes the type, so each
 * announces that interest). At its start it releases every device its edge owns and takes nothing for one lease
 * period: a node killed and started again finds its share held by others and gets it back without any device
 * commanded by two nodes at once.
 * <p>
 * A node that cannot reach its broker cannot renew its lease: once it has been out of its fabric for half a lease
 * period it releases every device (the others take them over when its lease lapses), and starts listening afresh when
 * it is back.
 * <p>
 * Threads: its own scheduler thread ({@code brain-iot-fabric-leases}) owns the table and calls the edge; the bus's
 * delivery thread hands each lease to it.
 */
@Component(service = SmartBehaviour.class, configurationPid = LeaseConfig.PID,
        configurationPolicy = ConfigurationPolicy.REQUIRE, immediate = true)
@SmartBehaviourDefinition(consumed = DeviceLease.class, author = "BRAIN-IoT fabric", name = "Device lease manager",
        description = "Moves the ownership of the fleet's devices between the nodes of a fabric")
public final class LeaseManager implements SmartBehaviour<DeviceLease> {

    private static final System.Logger LOG = System.getLogger(LeaseManager.class.getName());

    private final EventBus bus;
    private final DeviceOwnership ownership;
    /** Whether this node is in its fabric now (joined through its broker). */
    private final BooleanSupplier inFabric;
    private final long leaseMillis;
    private final long joinGraceMillis;
    private final ScheduledExecutorService thread;
    private final String self;

    // the scheduler thread only
    private LeaseTable table;
    private long outSinceNanos = -1;
    /** Whether the node was in its fabric at an earlier renewal (only the lease thread reads and writes it). */
    private boolean joinedBefore;
    private List<String> lapsedBefore = List.of();

    /**
     * On a node: the edge's ownership is an optional reference (a node without an edge still resolves the federation
     * bundle); without one the lease manager says so and leases nothing, and it starts again when an edge comes.
     */
    @Activate
    public LeaseManager(@Reference EventBus bus,
            @Reference(cardinality = ReferenceCardinality.OPTIONAL, policyOption = ReferencePolicyOption.GREEDY)
            DeviceOwnership ownership, @Reference FabricComponent fabric, LeaseConfig config) {
        this(bus, ownership, () -> {
            FabricNode node = fabric.node();
            return node != null && node.joined();
        }, config.lease_ms(), config.renew_ms(), config.join_grace_ms());
    }

    /** A lease manager whose node is in its fabric while {@code inFabric} says so. */
    LeaseManager(EventBus bus, DeviceOwnership ownership, BooleanSupplier inFabric, long leaseMs, long renewMs,
            long joinGraceMs) {
        this.bus = bus;
        this.ownership = ownership;
        this.inFabric = inFabric;
        this.leaseMillis = Math.max(100, leaseMs);
        this.joinGraceMillis = Math.max(leaseMillis, joinGraceMs);
        long renew = Math.max(10, Math.min(renewMs, leaseMillis / 2));
        this.thread = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "brain-iot-fabric-leases"));
        if (ownership == null) {
            this.self = null;
            LOG.log(System.Logger.Level.INFO, "Device leases ({0}): no edge on this node yet, nothing to lease until "
                    + "one comes (the leases start with it)", LeaseConfig.PID);
            return;
        }
        this.self = ownership.nodeName();
        thread.execute(() -> startListening("started"));
        thread.scheduleWithFixedDelay(this::safeTick, renew, renew, TimeUnit.MILLISECONDS);
        LOG.log(System.Logger.Level.INFO, "Device leases of node {0}: renewed every {1} ms, held {2} ms", self, renew,
                leaseMillis);
    }

    @Deactivate
    void deactivate() {
        thread.shutdownNow();
        try {
            thread.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void notify(DeviceLease lease) {
        if (self == null || lease.node == null || lease.share == null || lease.owned == null) {
            return;
        }
        long now = System.nanoTime();
        LeaseTable.Lease heard = new LeaseTable.Lease(lease.node, Set.copyOf(lease.share), Set.copyOf(lease.owned),
                now, TimeUnit.MILLISECONDS.toNanos(Math.max(1, lease.leaseMillis)));
        thread.execute(() -> {
            if (table != null) {
                table.heard(heard);
            }
        });
    }

    /** Release every device and take nothing for one lease period: first hear who holds what. */
    private void startListening(String why) {
        Set<String> released = ownership.release(ownership.owned());
        table = new LeaseTable(self, TimeUnit.MILLISECONDS.toNanos(leaseMillis), System.nanoTime(),
                TimeUnit.MILLISECONDS.toNanos(joinGraceMillis));
        LOG.log(System.Logger.Level.INFO, "Device leases of node {0}: {1}; released {2}, listening {3} ms before "
                + "taking any device, {4} ms before taking one nobody has claimed", self, why, released, leaseMillis,
                joinGraceMillis);
    }

    private void safeTick() {
        try {
            tick();
        } catch (RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "Device leases of node " + self + ": a renewal failed", e);
        }
    }

    private void tick() {
        long now = System.nanoTime();
        if (!inFabric.getAsBoolean()) {
            if (outSinceNanos < 0) {
                outSinceNanos = now;
            } else if (now - outSinceNanos > TimeUnit.MILLISECONDS.toNanos(leaseMillis / 2)
                    && !ownership.owned().isEmpty()) {
                startListening("out of its fabric for " + TimeUnit.NANOSECONDS.toMillis(now - outSinceNanos)
                        + " ms, its lease cannot be renewed");
            }
            return;
        }
        if (outSinceNanos >= 0) {
            outSinceNanos = -1;
            if (ownership.owned().isEmpty()) {
                startListening(joinedBefore ? "back in its fabric" : "joined its fabric");
            }
        }
        joinedBefore = true;
        List<String> lapsed = table.lapsed(now);
        if (!lapsed.equals(lapsedBefore) && !lapsed.isEmpty()) {
            LOG.log(System.Logger.Level.WARNING, "Device leases: the lease of {0} lapsed; its devices go to the "
                    + "nodes alive", lapsed);
        }
        lapsedBefore = lapsed;
        Set<String> share = ownership.share();
        LeaseTable.Plan plan = table.plan(now, ownership.fleet(), share, ownership.owned(), ownership::atRest);
        if (!plan.release().isEmpty()) {
            ownership.release(plan.release());
            LOG.log(System.Logger.Level.INFO, "Device leases of node {0}: released {1}", self, plan.release());
        }
        if (!plan.take().isEmpty()) {
            ownership.take(plan.take());
            LOG.log(System.Logger.Level.INFO, "Device leases of node {0}: took {1}", self, plan.take());
        }
        DeviceLease lease = new DeviceLease();
        lease.node = self;
        lease.share = new ArrayList<>(new TreeSet<>(share));
        lease.owned = new ArrayList<>(ownership.owned());
        lease.leaseMillis = leaseMillis;
        bus.deliver(lease);
    }
}
