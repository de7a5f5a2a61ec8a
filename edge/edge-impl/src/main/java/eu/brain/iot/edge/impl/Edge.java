package eu.brain.iot.edge.impl;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceReport;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.edge.model.api.PollStatistics;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceValue;
import eu.brain.iot.edge.model.api.UnknownResourceException;

/**
 * The edge without a framework, put together: one fleet thread; the {@link FleetApi} (the fleet's REST API)
 * shared by polling, mission tracking and commands; the {@link DeviceStore} where every change happens; the
 * {@link EdgeEvents} derived from its changes and the {@link Outbox} they leave by; the {@link FleetPoller}, which
 * only schedules polls, of the devices this node owns ({@link Ownership}); the {@link WorldReader}, which reads the
 * carts and the map from the fleet's world. The flow of a poll: poller, fleet API (HTTP threads), poller again (fleet
 * thread), store, then resource listeners (SSE) and edge events (bus). The DS component wraps it; tests and the
 * benchmark use it directly.
 * <p>
 * A fleet shared between the nodes of a fabric (a share other than {@code all}): every poll period the edge reports
 * the devices it owns ({@link DeviceReport}, on the fleet thread), and each device that changed at once, ahead of the
 * events of the change ({@link ChangeReports}); its model shows the devices the other nodes report beside its own
 * ({@link RemoteDevices}). A command reaches every node's edge; the owner performs it, the others leave it, except
 * the node it was published on when no node owns the device now: that one refuses it, so that the command has an
 * outcome.
 */
final class Edge implements DeviceModel, AutoCloseable {

    private final FleetApi api;
    private final Ownership ownership;
    private final Outbox outbox;
    private final DeviceStore store;
    private final FleetPoller poller;
    private final WorldReader world;
    private final CommandRunner commands;
    private final FleetThread fleet;
    private final String nodeName;
    private final RemoteDevices remote;
    private final EdgeLog log;

    /** An edge on a node without a name ({@value EdgeNode#DEFAULT_NAME}). */
    Edge(FleetSettings settings, EventSink events, EdgeLog log) {
        this(settings, EdgeNode.DEFAULT_NAME, events, log);
    }

    /** @param nodeName the node's name, given on every command to the fleet */
    Edge(FleetSettings settings, String nodeName, EventSink events, EdgeLog log) {
        FleetThread fleet = new FleetThread(nodeName);
        this.fleet = fleet;
        this.nodeName = nodeName;
        this.log = log;
        this.remote = new RemoteDevices(nodeName, freshMillis(settings), System::nanoTime);
        this.api = new FleetApi(nodeName);
        this.ownership = new Ownership(nodeName);
        this.outbox = new Outbox(events, log);
        this.store = new DeviceStore(new ChangeReports(new EdgeEvents(outbox, new MissionTracker(api, fleet, outbox,
                log)), this::reportDevice));
        this.poller = new FleetPoller(fleet, api, store, outbox, log, ownership);
        ownership.listener(poller::ownershipChanged);
        this.commands = new CommandRunner(api, store, event -> fleet.run(() -> outbox.publish(event),
                "publishing " + event.getClass().getSimpleName(), log));
        this.world = new WorldReader(fleet, api, store, log);
        poller.configure(settings);
        world.configure(settings);
        fleet.run(this::report, "the first report of this node's devices", log);
    }

    void configure(FleetSettings settings) {
        poller.configure(settings);
        world.configure(settings);
        remote.freshMillis(freshMillis(settings));
    }

    /**
     * How long another node's report holds: several of its periods, and shorter than a device lease (2 s), so that
     * a command is not left to a node that died and whose devices are about to change hands.
     */
    static long freshMillis(FleetSettings settings) {
        return Math.min(REPORT_HOLDS_MAX_MILLIS, Math.max(REPORT_HOLDS_MIN_MILLIS,
                REPORT_HOLDS_PERIODS * settings.periodMillis()));
    }

    private static final long REPORT_HOLDS_MIN_MILLIS = 1_000;
    private static final long REPORT_HOLDS_MAX_MILLIS = 1_500;
    private static final long REPORT_HOLDS_PERIODS = 4;
    /** The report's period before the edge has settings (the poll period's default). */
    private static final long DEFAULT_REPORT_MILLIS = 500;

    /** On the fleet thread, every poll period: the devices this node owns, to the other nodes of a shared fleet. */
    private void report() {
        FleetSettings s = api.settings();
        try {
            publishReport(s, store.snapshots());
        } finally {
            try {
                fleet.schedule(this::report, s == null ? DEFAULT_REPORT_MILLIS : s.periodMillis(),
                        TimeUnit.MILLISECONDS);
            } catch (RejectedExecutionException closing) {
                // the edge is closing: no more reports
            }
        }
    }

    /** On the fleet thread, when a device this node owns changed: that device alone, to the other nodes. */
    private void reportDevice(String id) {
        store.snapshot(id).ifPresent(device -> publishReport(api.settings(), List.of(device)));
    }

    /** A report of these devices of this node's, when the fleet is shared and there is any robot or door in them. */
    private void publishReport(FleetSettings s, List<ProviderSnapshot> devices) {
        if (s == null || s.share().mode() == Share.Mode.ALL) {
            return;
        }
        DeviceReport r = new DeviceReport();
        r.node = nodeName;
        r.devices = RemoteDevices.encode(devices);
        if (!r.devices.isEmpty()) {
            outbox.publish(r);
        }
    }

    /** Another node's report (on the bus's thread). */
    void reported(DeviceReport r) {
        int skipped = remote.accept(r, id -> store.contains(id));
        if (skipped > 0) {
            log.warn("a device report from node " + r.node + " had " + skipped + " malformed entries, skipped");
        }
    }

    FleetSettings settings() {
        return api.settings();
    }

    /** Which devices this node owns, and their hand-over at run time. */
    DeviceOwnership ownership() {
        return ownership;
    }

    /** @return whether this node owns the device and it is at rest ({@link Resting}) */
    boolean atRest(String deviceId) {
        return ownership.owns(deviceId) && provider(deviceId).map(Resting::atRest).orElse(false);
    }

    PollStats.Snapshot pollStats() {
        return poller.stats().snapshot();
    }

    /** Polling and publishing counters, as the exported monitoring API shows them. */
    PollStatistics statistics() {
        PollStats.Snapshot s = pollStats();
        PollStatistics dto = new PollStatistics();
        FleetSettings settings = settings();
        dto.fleetUrl = settings == null ? null : settings.baseUrl().toString();
        dto.sent = s.sent();
        dto.answered = s.answered();
        dto.failed = s.failed();
        dto.skipped = s.skipped();
        dto.onTime = s.onTime();
        dto.late = s.late();
        dto.seconds = s.seconds();
        dto.deviationP50Millis = s.deviationP50Millis();
        dto.deviationP99Millis = s.deviationP99Millis();
        dto.eventsWaiting = outbox.depth();
        dto.eventsRefused = outbox.refusals();
        dto.positionsCoalesced = outbox.coalesced();
        return dto;
    }

    void resetPollStats() {
        poller.stats().reset();
    }

    /** Performs a command; the outcome is published on the bus too. */
    CompletableFuture<CommandOutcome> execute(EdgeCommand command) {
        return commands.run(command);
    }

    /**
     * A command from the bus, which brings every command to every node's edge: performed when this node has the
     * device; otherwise left to the other nodes, except on the node it was published on when no node reports the
     * device now: refused there, saying why (no such device; or its owner stopped reporting it, its devices changing
     * hands), so that every command has one outcome.
     *
     * @param publishedHere whether the command was published on this node
     * @return the outcome, or empty when the command is another node's to perform
     */
    Optional<CompletableFuture<CommandOutcome>> execute(EdgeCommand command, boolean publishedHere) {
        String device = command.deviceId;
        if (device != null && store.contains(device)) {
            return Optional.of(commands.run(command));
        }
        if (!publishedHere || remote.owner(device).isPresent()) {
            return Optional.empty();
        }
        Optional<String> last = remote.lastOwner(device);
        if (last.isEmpty()) {
            return Optional.of(commands.run(command)); // refused: no device (id), saying which there are
        }
        return Optional.of(commands.refuse(command, "no node owns " + device + " now: node " + last.get()
                + ", which owned it, has not reported it for over " + freshMillis(api.settings())
                + " ms (a lease lapsing hands its devices to the other nodes); send the command again"));
    }

    @Override
    public List<ProviderSnapshot> providers() {
        List<ProviderSnapshot> local = store.snapshots();
        List<ProviderSnapshot> others = remote.snapshots();
        if (others.isEmpty()) {
            return local;
        }
        List<ProviderSnapshot> all = new ArrayList<>(local);
        for (ProviderSnapshot p : others) {
            if (!store.contains(p.id())) {
                all.add(p);
            }
        }
        all.sort(Comparator.comparing(ProviderSnapshot::id));
        return all;
    }

    @Override
    public Optional<ProviderSnapshot> provider(String providerId) {
        Optional<ProviderSnapshot> local = store.snapshot(providerId);
        return local.isPresent() ? local : remote.snapshot(providerId);
    }

    @Override
    public Optional<ResourceValue> resource(String providerId, String service, String resource) {
        if (providerId != null && store.contains(providerId)) {
            return store.resource(providerId, service, resource);
        }
        return remote.snapshot(providerId).map(p -> p.services().get(service)).map(r -> r.get(resource));
    }

    @Override
    public Subscription subscribe(String providerId, String service, ResourceListener listener) {
        return store.subscribe(providerId, service, listener);
    }

    @Override
    public CompletionStage<CommandOutcome> act(String providerId, String service, String action,
            Map<String, Object> parameters) {
        DeviceKind kind = store.kind(providerId);
        if (kind == null) {
            throw new UnknownResourceException("no provider '" + providerId + "' (robots: "
                    + store.ids(DeviceKind.ROBOT) + ", doors: " + store.ids(DeviceKind.DOOR) + ")");
        }
        return execute(Actions.command(providerId, kind, service, action, parameters == null ? Map.of() : parameters));
    }

    @Override
    public void close() {
        poller.close();
        api.close();
    }
}
