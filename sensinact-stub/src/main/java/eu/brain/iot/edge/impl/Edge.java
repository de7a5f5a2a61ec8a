package eu.brain.iot.edge.impl;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.PollStatistics;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceValue;
import eu.brain.iot.edge.model.api.UnknownResourceException;

/**
 * The edge without a framework: the device model, the poller and the command runner put together. The DS
 * component wraps it; tests and the benchmark use it directly.
 */
final class Edge implements DeviceModel, AutoCloseable {

    private final DeviceStore store = new DeviceStore();
    private final FleetPoller poller;
    private final CommandRunner commands;

    Edge(FleetSettings settings, EventSink events, EdgeLog log) {
        this.poller = new FleetPoller(store, events, log);
        this.commands = new CommandRunner(poller, store, poller::publishFromAnyThread);
        poller.configure(settings);
    }

    void configure(FleetSettings settings) {
        poller.configure(settings);
    }

    FleetSettings settings() {
        return poller.settings();
    }

    PollStats.Snapshot pollStats() {
        return poller.stats().snapshot();
    }

    /** Polling and publishing counters, as the exported monitoring API shows them. */
    PollStatistics statistics() {
        PollStats.Snapshot s = pollStats();
        Outbox outbox = poller.outbox();
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
        String kind = store.kind(providerId);
        if (kind == null) {
            throw new UnknownResourceException("no provider '" + providerId + "' (robots: "
                    + store.ids(DeviceKind.ROBOT.label) + ", doors: " + store.ids(DeviceKind.DOOR.label) + ")");
        }
        DeviceKind k = DeviceKind.ROBOT.label.equals(kind) ? DeviceKind.ROBOT : DeviceKind.DOOR;
        return execute(Actions.command(providerId, k, service, action, parameters == null ? Map.of() : parameters));
    }

    @Override
    public void close() {
        poller.close();
    }
}
