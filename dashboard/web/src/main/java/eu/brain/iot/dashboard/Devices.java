package eu.brain.iot.dashboard;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;

import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * The dashboard's copy of the edge's device model: every provider (robots, doors, and carts and the map once the
 * edge has them) with its status and resource values, and which providers changed since the last event. The page
 * receives whole providers, so it never has to merge resources itself.
 * <p>
 * Thread: owned by the dashboard's thread ({@link Hub}); not safe for any other.
 */
final class Devices {

    /** Told when a door's state changes (for the door-openings counter). */
    interface DoorWatcher {
        void doorState(String doorId, String before, String after);
    }

    private static final class Device {
        final String id;
        String kind;
        ResourceStatus status = ResourceStatus.OK;
        String reason;
        final Map<String, Map<String, Object>> values = new TreeMap<>();

        Device(String id) {
            this.id = id;
        }
    }

    private final Map<String, Device> devices = new TreeMap<>();
    /** Providers to send whole (new, reloaded). */
    private final Set<String> changed = new LinkedHashSet<>();
    /** Of the others: the resources that changed since the last event, by provider, then service. */
    private final Map<String, Map<String, Map<String, Object>>> partial = new LinkedHashMap<>();
    private final Set<String> removed = new LinkedHashSet<>();
    private final DoorWatcher doors;

    Devices(DoorWatcher doors) {
        this.doors = doors;
    }

    /** Takes a provider whole, as the model shows it now. */
    void load(ProviderSnapshot p) {
        Device d = devices.computeIfAbsent(p.id(), Device::new);
        d.kind = p.kind();
        d.status = p.status();
        d.reason = p.reason();
        d.values.clear();
        p.services().forEach((service, resources) -> resources.forEach(
                (name, v) -> d.values.computeIfAbsent(service, s -> new TreeMap<>()).put(name, v.value())));
        changed.add(p.id());
        partial.remove(p.id());
        removed.remove(p.id());
    }

    /**
     * Applies one change. Returns {@code true} when the provider is new or its status changed: the caller then
     * reloads it from the model, which knows its kind and the reason of its status.
     */
    boolean apply(ResourceValue v) {
        Device d = devices.get(v.provider());
        boolean reload = d == null || d.status != v.status();
        if (d == null) {
            d = new Device(v.provider());
            devices.put(d.id, d);
        }
        Map<String, Object> service = d.values.computeIfAbsent(v.service(), s -> new TreeMap<>());
        Object before = service.put(v.resource(), v.value());
        if ("door".equals(v.service()) && "state".equals(v.resource()) && before != null
                && !Objects.equals(before, v.value())) {
            doors.doorState(d.id, String.valueOf(before), String.valueOf(v.value()));
        }
        d.status = v.status();
        if (!changed.contains(d.id)) {
            partial.computeIfAbsent(d.id, id -> new TreeMap<>()).computeIfAbsent(v.service(), s -> new TreeMap<>())
                    .put(v.resource(), v.value());
        }
        removed.remove(d.id);
        return reload;
    }

    /** Forgets providers the model no longer has. */
    void retain(Set<String> ids) {
        for (String id : new ArrayList<>(devices.keySet())) {
            if (!ids.contains(id)) {
                devices.remove(id);
                changed.remove(id);
                partial.remove(id);
                removed.add(id);
            }
        }
    }

    Set<String> ids() {
        return devices.keySet();
    }

    /** A value of a provider, or {@code null}. */
    Object value(String id, String service, String resource) {
        Device d = devices.get(id);
        Map<String, Object> s = d == null ? null : d.values.get(service);
        return s == null ? null : s.get(resource);
    }

    boolean hasChanges() {
        return !changed.isEmpty() || !partial.isEmpty() || !removed.isEmpty();
    }

    /**
     * The providers changed since the last call, and forgets that they changed: new or reloaded ones whole
     * ({@code "full": true}), the others with their status and only the resources that changed, which the page
     * merges into what it has (a robot that moved costs its position, not its dozen other resources).
     */
    List<Map<String, Object>> takeChanged() {
        List<Map<String, Object>> out = new ArrayList<>(changed.size() + partial.size());
        for (String id : changed) {
            Device d = devices.get(id);
            if (d != null) {
                Map<String, Object> m = view(d);
                m.put("full", true);
                out.add(m);
            }
        }
        partial.forEach((id, values) -> {
            Device d = devices.get(id);
            if (d != null) {
                Map<String, Object> m = new LinkedHashMap<>();
                m.put("id", id);
                m.put("status", d.status.name());
                m.put("values", values);
                out.add(m);
            }
        });
        changed.clear();
        partial.clear();
        return out;
    }

    List<String> takeRemoved() {
        List<String> out = List.copyOf(removed);
        removed.clear();
        return out;
    }

    /** Every provider, sorted by id. */
    List<Map<String, Object>> all() {
        List<Map<String, Object>> out = new ArrayList<>(devices.size());
        devices.values().forEach(d -> out.add(view(d)));
        return out;
    }

    private static Map<String, Object> view(Device d) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("id", d.id);
        m.put("kind", d.kind);
        m.put("status", d.status.name());
        m.put("reason", d.reason);
        m.put("values", d.values);
        return m;
    }
}
