package eu.brain.iot.edge.rest.integration;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CopyOnWriteArrayList;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;
import eu.brain.iot.edge.model.api.UnknownResourceException;

/**
 * The device model the REST API serves in these tests: one robot and one door whose changes the test makes
 * ({@link #emit}), as fast as it likes, and actions that are accepted at once. The HTTP surface is what is under
 * test; the whole edge behind it (polling robot-sim) is tested in edge-impl.
 * <p>
 * Threads: the test's; {@link #emit} calls the listeners on the caller's thread, as the edge's fleet thread would.
 */
final class ScriptedModel implements DeviceModel {

    private record Listener(String provider, String service, ResourceListener listener) {
    }

    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    final List<Map<String, Object>> acts = new CopyOnWriteArrayList<>();

    private static ProviderSnapshot robot() {
        Instant now = Instant.now();
        return new ProviderSnapshot("robot1", "robot", ResourceStatus.OK, now, null,
                Map.of("position", Map.of("x", value("robot1", "position", "x", 1),
                        "y", value("robot1", "position", "y", 2))),
                Map.of("control", List.of("goTo(x,y)", "pick", "place")));
    }

    private static ProviderSnapshot door() {
        return new ProviderSnapshot("door1", "door", ResourceStatus.OK, Instant.now(), null,
                Map.of("door", Map.of("state", value("door1", "door", "state", "closed"))),
                Map.of("control", List.of("open", "close")));
    }

    static ResourceValue value(String provider, String service, String resource, Object v) {
        return new ResourceValue(provider, service, resource, v, Instant.now(), ResourceStatus.OK);
    }

    @Override
    public List<ProviderSnapshot> providers() {
        return List.of(door(), robot());
    }

    @Override
    public Optional<ProviderSnapshot> provider(String providerId) {
        return providers().stream().filter(p -> p.id().equals(providerId)).findFirst();
    }

    @Override
    public Optional<ResourceValue> resource(String providerId, String service, String resource) {
        return provider(providerId).map(p -> p.services().getOrDefault(service, Map.of()).get(resource));
    }

    @Override
    public Subscription subscribe(String providerId, String service, ResourceListener listener) {
        Listener l = new Listener(providerId, service, listener);
        listeners.add(l);
        return () -> listeners.remove(l);
    }

    /** A change, told to every listener whose filter takes it. */
    void emit(ResourceValue v) {
        for (Listener l : listeners) {
            if ((l.provider == null || l.provider.equals(v.provider()))
                    && (l.service == null || l.service.equals(v.service()))) {
                l.listener.changed(v);
            }
        }
    }

    int subscribers() {
        return listeners.size();
    }

    @Override
    public CompletionStage<CommandOutcome> act(String providerId, String service, String action,
            Map<String, Object> parameters) {
        ProviderSnapshot p = provider(providerId)
                .orElseThrow(() -> new UnknownResourceException("no provider '" + providerId + "'"));
        if (p.actions().getOrDefault(service, List.of()).stream().noneMatch(a -> a.startsWith(action))) {
            throw new UnknownResourceException(providerId + " has no action '" + action + "'");
        }
        acts.add(parameters);
        CommandOutcome o = new CommandOutcome();
        o.deviceId = providerId;
        o.command = action;
        o.accepted = true;
        o.status = 200;
        return CompletableFuture.completedFuture(o);
    }
}
