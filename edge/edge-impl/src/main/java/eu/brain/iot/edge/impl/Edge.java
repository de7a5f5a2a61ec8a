package eu.brain.iot.edge.impl;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;

import eu.brain.iot.edge.api.CommandOutcome;
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
 * only schedules polls, of the devices this node owns ({@link Ownership}); the {@link WorldReader}, which reads the carts and the map from the fleet's world. The flow of a poll: poller, fleet API (HTTP threads), poller again (fleet thread), store,
 * then resource listeners (SSE) and edge events (bus). The DS component wraps it; tests and the benchmark use it
 * directly.
 */
final class Edge implements DeviceModel, AutoCloseable {

    private final FleetApi api;
    private final Ownership ownership;
    private final Outbox outbox;
    private final DeviceStore store;
    private final FleetPoller poller;
    private final WorldReader world;
    private final CommandRunner commands;

    /** An edge on a node without a name ({@value EdgeNode#DEFAULT_NAME}). */
    Edge(FleetSettings settings, EventSink events, EdgeLog log) {
        this(settings, EdgeNode.DEFAULT_NAME, events, log);
    }

    /** @param nodeName the node's name, given on every command to the fleet */
    Edge(FleetSettings settings, String nodeName, EventSink events, EdgeLog log) {
        FleetThread fleet = new FleetThread();
        this.api = new FleetApi(nodeName);
        this.ownership = new Ownership(nodeName);
        this.outbox = new Outbox(events, log);
        this.store = new DeviceStore(new EdgeEvents(outbox, new MissionTracker(api, fleet, outbox, log)));
        this.poller = new FleetPoller(fleet, api, store, outbox, log, ownership);
        ownership.listener(poller::ownershipChanged);
        this.commands = new CommandRunner(api, store, event -> fleet.run(() -> outbox.publish(event),
                "publishing " + event.getClass().getSimpleName(), log));
        this.world = new WorldReader(fleet, api, store, log);
        poller.configure(settings);
        world.configure(settings);
    }

    void configure(FleetSettings settings) {
        poller.configure(settings);
        world.configure(settings);
    }

    FleetSettings settings() {
        return api.settings();
    }

    /** Which devices this node owns, and their hand-over at run time. */
    DeviceOwnership ownership() {
        return ownership;
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

    @Override
    public List<ProviderSnapshot> providers() {
        return store.snapshots();
    }

    @Override
    public Optional<ProviderSnapshot> provider(String providerId) {
        return store.snapshot(providerId);
    }

    @Override
    public Optional<ResourceValue> resource(String providerId, String service, String resource) {
        return store.resource(providerId, service, resource);
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
