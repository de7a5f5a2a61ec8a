package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;

import eu.brain.iot.edge.model.api.DeviceModel.Subscription;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * The device model's data: providers, their services and resources.
 * <p>
 * Ownership: only the fleet thread ({@link FleetPoller}) writes; any thread reads. Values are immutable
 * {@link ResourceValue}s in concurrent maps, so a reader sees each resource whole, possibly one poll old.
 * Listeners are called on the writing thread, in the order of the writes.
 */
final class DeviceStore {

    private final Map<String, Provider> providers = new ConcurrentHashMap<>();
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();

    /** A device and what is known of it. */
    private static final class Provider {
        final String id;
        final String kind;
        final Map<String, List<String>> actions;
        final Map<String, Map<String, ResourceValue>> services = new ConcurrentHashMap<>();
        volatile ResourceStatus status = ResourceStatus.STALE;
        volatile String reason = "not polled yet";
        volatile Instant lastPoll;

        Provider(String id, String kind, Map<String, List<String>> actions) {
            this.id = id;
            this.kind = kind;
            this.actions = actions;
        }
    }

    private record Listener(String provider, String service, ResourceListener target) {
        boolean wants(ResourceValue v) {
            return (provider == null || provider.equals(v.provider()))
                    && (service == null || service.equals(v.service()));
        }
    }

    void add(String id, String kind, Map<String, List<String>> actions) {
        providers.putIfAbsent(id, new Provider(id, kind, actions));
    }

    void remove(String id) {
        providers.remove(id);
    }

    boolean contains(String id) {
        return providers.containsKey(id);
    }

    /** Sets a resource; listeners hear of it only when the value changed. */
    void set(String providerId, String service, String resource, Object value, Instant now) {
        Provider p = providers.get(providerId);
        if (p == null) {
            return;
        }
        Map<String, ResourceValue> resources = p.services.computeIfAbsent(service, s -> new ConcurrentHashMap<>());
        ResourceValue old = resources.get(resource);
        if (old != null && Objects.equals(old.value(), value) && old.status() == p.status) {
            return;
        }
        ResourceValue updated = new ResourceValue(providerId, service, resource, value, now, p.status);
        resources.put(resource, updated);
        fire(updated);
    }

    /** A poll answered: the provider's resources are current again. */
    void answered(String providerId, Instant now) {
        Provider p = providers.get(providerId);
        if (p != null) {
            p.lastPoll = now;
            status(p, ResourceStatus.OK, null);
        }
    }

    /** A poll failed: the provider's resources keep their values with this status. */
    void failed(String providerId, ResourceStatus status, String reason) {
        Provider p = providers.get(providerId);
        if (p != null) {
            status(p, status, reason);
        }
    }

    private void status(Provider p, ResourceStatus status, String reason) {
        p.reason = reason;
        if (p.status == status) {
            return;
        }
        p.status = status;
        for (Map<String, ResourceValue> resources : p.services.values()) {
            for (ResourceValue v : resources.values()) {
                ResourceValue updated = new ResourceValue(v.provider(), v.service(), v.resource(), v.value(),
                        v.timestamp(), status);
                resources.put(v.resource(), updated);
                fire(updated);
            }
        }
    }

    private void fire(ResourceValue value) {
        for (Listener l : listeners) {
            if (l.wants(value)) {
                l.target().changed(value);
            }
        }
    }

    Subscription subscribe(String provider, String service, ResourceListener listener) {
        Listener l = new Listener(provider, service, Objects.requireNonNull(listener, "listener"));
        listeners.add(l);
        return () -> listeners.remove(l);
    }

    List<ProviderSnapshot> snapshots() {
        List<ProviderSnapshot> all = new ArrayList<>();
        for (String id : new TreeMap<>(providers).keySet()) {
            snapshot(id).ifPresent(all::add);
        }
        return all;
    }

    Optional<ProviderSnapshot> snapshot(String id) {
        Provider p = id == null ? null : providers.get(id);
        if (p == null) {
            return Optional.empty();
        }
        Map<String, Map<String, ResourceValue>> services = new LinkedHashMap<>();
        new TreeMap<>(p.services).forEach((name, resources) -> services.put(name,
                Collections.unmodifiableMap(new TreeMap<>(resources))));
        return Optional.of(new ProviderSnapshot(p.id, p.kind, p.status, p.lastPoll, p.reason,
                Collections.unmodifiableMap(services), p.actions));
    }

    Optional<ResourceValue> resource(String provider, String service, String resource) {
        Provider p = provider == null ? null : providers.get(provider);
        if (p == null) {
            return Optional.empty();
        }
        Map<String, ResourceValue> resources = p.services.get(service);
        return resources == null ? Optional.empty() : Optional.ofNullable(resources.get(resource));
    }

    String kind(String id) {
        Provider p = providers.get(id);
        return p == null ? null : p.kind;
    }

    List<String> ids(String kind) {
        List<String> ids = new ArrayList<>();
        providers.values().forEach(p -> {
            if (p.kind.equals(kind)) {
                ids.add(p.id);
            }
        });
        Collections.sort(ids);
        return ids;
    }
}
