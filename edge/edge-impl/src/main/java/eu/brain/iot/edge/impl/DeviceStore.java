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
 * The device model: providers, their services and resources, and the one place where a change of the fleet as
 * the edge sees it happens. A poll's answer enters here ({@link #update}); from what changed the store tells
 * every {@link ResourceListener} (the SSE streams, in-framework subscribers) each changed resource, then the
 * {@link ModelChanges} (the edge's events on the bus) what the provider did. So both leave from one change, in
 * the same order, as sensiNact's model update feeds its notification accumulator.
 * <p>
 * Ownership: only the fleet thread ({@link FleetPoller}) writes, and the listeners are called on it, in the order
 * of the writes; any thread reads. Values are immutable {@link ResourceValue}s in concurrent maps, so a reader
 * sees each resource whole, possibly one poll old. {@link Provider#last} and {@link Provider#downSince} belong
 * to the fleet thread.
 * <p>
 * Snapshots are read far more often than devices are polled (every robot behaviour's look reads the whole fleet),
 * so each provider's snapshot, and the sorted list of providers, is built once per change and kept: a write ends by
 * moving the provider's version on ({@link #changed}), and a snapshot built at an older version is built again. A
 * snapshot built while a write runs carries the version before it, so the next read after the write builds it anew.
 */
final class DeviceStore {

    private final Map<String, Provider> providers = new ConcurrentHashMap<>();
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private final ModelChanges changes;
    /** Moves on whenever a provider is added or removed; written by the fleet thread only. */
    private volatile long membership;
    private volatile Kept<List<String>> sortedIds;

    DeviceStore(ModelChanges changes) {
        this.changes = changes;
    }

    /** A device and what is known of it. */
    private static final class Provider {
        final String id;
        final DeviceKind kind;
        final Map<String, Map<String, ResourceValue>> services = new ConcurrentHashMap<>();
        volatile ResourceStatus status = ResourceStatus.STALE;
        volatile String reason = "not polled yet";
        volatile Instant lastPoll;
        /** The answer the values came from; {@code null} before the first. */
        DeviceAnswer last;
        /** When it became unreachable ({@link System#currentTimeMillis()}). */
        long downSince;
        /** Moves on after every write to the provider; written by the fleet thread only. */
        volatile long version;
        volatile Kept<ProviderSnapshot> snapshot;

        Provider(String id, DeviceKind kind) {
            this.id = id;
            this.kind = kind;
        }
    }

    /** A value built from the store at a version of it. */
    private record Kept<T>(long version, T value) {
    }

    private record Listener(String provider, String service, ResourceListener target) {
        boolean wants(ResourceValue v) {
            return (provider == null || provider.equals(v.provider()))
                    && (service == null || service.equals(v.service()));
        }
    }

    void add(String id, DeviceKind kind) {
        if (providers.putIfAbsent(id, new Provider(id, kind)) == null) {
            membership++;
        }
    }

    /** The provider leaves the model; {@code reason} says why (the bus hears it for a robot or a door). */
    void remove(String id, String reason) {
        Provider p = providers.remove(id);
        if (p != null) {
            membership++;
            changes.removed(id, p.kind, reason);
        }
    }

    /**
     * The device is polled at another fleet URL from now on ({@code fleet.url} changed), under the same id. Its
     * values were the old fleet's, so they are dropped (a behaviour must not act on another fleet's position), and
     * its next answer counts as its first: its events are derived afresh (its position announced, no mission end
     * taken from the other fleet's history). An {@code UNREACHABLE} device stays so, with its time of failure, until
     * the new fleet answers for it: then {@link #answered} tells its recovery, so that a behaviour told
     * {@code DeviceUnreachable} hears {@code DeviceRecovered}. Any other device is {@code STALE} until then.
     */
    void moved(String id, String reason) {
        Provider p = providers.get(id);
        if (p == null) {
            return;
        }
        if (p.status == ResourceStatus.UNREACHABLE) {
            p.reason = reason + " (unreachable since " + Instant.ofEpochMilli(p.downSince) + ")";
        } else {
            status(p, ResourceStatus.STALE, reason); // listeners hear each resource go STALE before it is dropped
        }
        p.services.clear();
        p.last = null;
        changed(p);
        changes.moved(id);
    }

    /**
     * A poll brought a new answer: the provider is current again, its resources take the answer's values; then
     * the changes are told (recovery first, if it was unreachable).
     */
    void update(String providerId, DeviceAnswer answer, Instant now) {
        Provider p = providers.get(providerId);
        if (p == null) {
            return;
        }
        answered(p, now);
        for (DeviceAnswer.Resource r : answer.resources()) {
            set(p, r.service(), r.resource(), r.value(), now);
        }
        DeviceAnswer before = p.last;
        p.last = answer;
        changed(p);
        changes.answered(providerId, before, answer, now);
    }

    /** A poll brought the same answer as last time: the provider is current again, no value changed. */
    void unchanged(String providerId, Instant now) {
        Provider p = providers.get(providerId);
        if (p != null) {
            answered(p, now);
            changed(p);
        }
    }

    private void answered(Provider p, Instant now) {
        p.lastPoll = now;
        boolean wasDown = p.status == ResourceStatus.UNREACHABLE;
        status(p, ResourceStatus.OK, null);
        if (wasDown) {
            changes.recovered(p.id, p.kind, System.currentTimeMillis() - p.downSince);
        }
    }

    /** A poll failed: the provider's resources keep their values, now {@code STALE}. */
    void stale(String providerId, String reason) {
        Provider p = providers.get(providerId);
        if (p != null) {
            status(p, ResourceStatus.STALE, reason);
            changed(p);
        }
    }

    /** The device failed {@code failures} polls in a row: its resources are {@code UNREACHABLE}, once told. */
    void unreachable(String providerId, String reason, int failures) {
        Provider p = providers.get(providerId);
        if (p == null) {
            return;
        }
        boolean news = p.status != ResourceStatus.UNREACHABLE;
        status(p, ResourceStatus.UNREACHABLE, reason);
        changed(p);
        if (news) {
            p.downSince = System.currentTimeMillis();
            changes.unreachable(providerId, p.kind, reason, failures);
        }
    }

    boolean contains(String id) {
        return providers.containsKey(id);
    }

    /** Sets a resource; listeners hear of it only when the value changed. */
    private void set(Provider p, String service, String resource, Object value, Instant now) {
        Map<String, ResourceValue> resources = p.services.computeIfAbsent(service, s -> new ConcurrentHashMap<>());
        ResourceValue old = resources.get(resource);
        if (old != null && Objects.equals(old.value(), value) && old.status() == p.status) {
            return;
        }
        ResourceValue updated = new ResourceValue(p.id, service, resource, value, now, p.status);
        resources.put(resource, updated);
        fire(updated);
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

    /** Ends a write to the provider: snapshots built before it are built again when next read. */
    private static void changed(Provider p) {
        p.version++; // one writer (the fleet thread): the increment is not contended
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

    /** @return every provider's snapshot, by id */
    List<ProviderSnapshot> snapshots() {
        long version = membership;
        Kept<List<String>> ids = sortedIds;
        if (ids == null || ids.version() != version) {
            ids = new Kept<>(version, List.copyOf(new TreeMap<>(providers).keySet()));
            sortedIds = ids;
        }
        List<ProviderSnapshot> all = new ArrayList<>(ids.value().size());
        for (String id : ids.value()) {
            snapshot(id).ifPresent(all::add);
        }
        return all;
    }

    Optional<ProviderSnapshot> snapshot(String id) {
        Provider p = id == null ? null : providers.get(id);
        if (p == null) {
            return Optional.empty();
        }
        long version = p.version;
        Kept<ProviderSnapshot> kept = p.snapshot;
        if (kept == null || kept.version() != version) {
            kept = new Kept<>(version, build(p));
            p.snapshot = kept;
        }
        return Optional.of(kept.value());
    }

    private static ProviderSnapshot build(Provider p) {
        Map<String, Map<String, ResourceValue>> services = new LinkedHashMap<>();
        new TreeMap<>(p.services).forEach((name, resources) -> services.put(name,
                Collections.unmodifiableMap(new TreeMap<>(resources))));
        return new ProviderSnapshot(p.id, p.kind.label, p.status, p.lastPoll, p.reason,
                Collections.unmodifiableMap(services), p.kind.actions);
    }

    Optional<ResourceValue> resource(String provider, String service, String resource) {
        Provider p = provider == null ? null : providers.get(provider);
        if (p == null) {
            return Optional.empty();
        }
        Map<String, ResourceValue> resources = p.services.get(service);
        return resources == null ? Optional.empty() : Optional.ofNullable(resources.get(resource));
    }

    DeviceKind kind(String id) {
        Provider p = providers.get(id);
        return p == null ? null : p.kind;
    }

    List<String> ids(DeviceKind kind) {
        List<String> ids = new ArrayList<>();
        providers.values().forEach(p -> {
            if (p.kind == kind) {
                ids.add(p.id);
            }
        });
        Collections.sort(ids);
        return ids;
    }
}
