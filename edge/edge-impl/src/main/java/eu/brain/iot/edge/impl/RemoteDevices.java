package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;
import java.util.function.Predicate;
import java.util.regex.Pattern;

import eu.brain.iot.edge.api.DeviceReport;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * The robots and doors other nodes of the fabric own, as their edges report them ({@link DeviceReport}): this
 * node's device model shows them beside its own, each with the service {@value #FABRIC_SERVICE} and its resource
 * {@value #OWNER_RESOURCE}, the owning node. For each device the report with the newest poll wins, whichever node
 * sent it (ownership moves between nodes); a device this node owns is never taken from a report. A device whose
 * owner has not reported it for {@link #freshMillis} shows {@code STALE}, with its last values and the reason.
 * <p>
 * Threads: reports arrive on the bus's thread, readers are any threads; the entries are immutable and replaced
 * whole in a concurrent map (newest poll wins, by {@code merge}).
 */
final class RemoteDevices {

    /** The service of a device another node owns. */
    static final String FABRIC_SERVICE = "fabric";
    /** Its resource: the owning node's name. */
    static final String OWNER_RESOURCE = "node";

    private static final Pattern ID = Pattern.compile("[A-Za-z0-9_.-]{1,128}");
    private static final int MAX_DEVICES_PER_REPORT = 100_000;

    private record Entry(String node, ProviderSnapshot snapshot, long lastPollMillis, long receivedNanos) {
    }

    private final String localNode;
    private final LongSupplier nanoClock;
    private final Map<String, Entry> devices = new ConcurrentHashMap<>();
    private final AtomicLong malformed = new AtomicLong();
    private volatile long freshMillis;

    /**
     * @param localNode   this node's name: its own reports are not taken
     * @param freshMillis how long a report holds before its devices show {@code STALE}
     */
    RemoteDevices(String localNode, long freshMillis, LongSupplier nanoClock) {
        this.localNode = localNode;
        this.freshMillis = freshMillis;
        this.nanoClock = nanoClock;
    }

    void freshMillis(long millis) {
        this.freshMillis = millis;
    }

    /**
     * Takes another node's report; entries that are not what {@link DeviceReport} says are skipped and counted.
     *
     * @param ownedHere whether this node's edge has the device (then the report's entry is not taken)
     * @return the number of entries skipped as malformed
     */
    int accept(DeviceReport report, Predicate<String> ownedHere) {
        if (report == null || report.node == null || report.node.equals(localNode) || report.devices == null) {
            return 0;
        }
        int skipped = 0;
        long now = nanoClock.getAsLong();
        int n = 0;
        for (Map<String, Object> device : report.devices) {
            if (++n > MAX_DEVICES_PER_REPORT) {
                break;
            }
            Entry e = entry(report.node, device, now);
            if (e == null) {
                skipped++;
                continue;
            }
            if (ownedHere.test(e.snapshot().id())) {
                devices.remove(e.snapshot().id());
                continue;
            }
            devices.merge(e.snapshot().id(), e, (old, next) -> next.lastPollMillis() >= old.lastPollMillis() ? next : old);
        }
        malformed.addAndGet(skipped);
        return skipped;
    }

    /** @return the device as its owner last reported it, {@code STALE} when the report is older than allowed */
    Optional<ProviderSnapshot> snapshot(String id) {
        Entry e = id == null ? null : devices.get(id);
        return e == null ? Optional.empty() : Optional.of(aged(e));
    }

    /** @return every device other nodes reported, by id */
    List<ProviderSnapshot> snapshots() {
        List<ProviderSnapshot> all = new ArrayList<>();
        for (Entry e : new TreeMap<>(devices).values()) {
            all.add(aged(e));
        }
        return all;
    }

    /** @return the node that owns the device by a report that still holds, or empty */
    Optional<String> owner(String id) {
        Entry e = id == null ? null : devices.get(id);
        return e == null || stale(e) ? Optional.empty() : Optional.of(e.node());
    }

    /** @return the node that reported the device last, however long ago, or empty */
    Optional<String> lastOwner(String id) {
        Entry e = id == null ? null : devices.get(id);
        return e == null ? Optional.empty() : Optional.of(e.node());
    }

    long malformed() {
        return malformed.get();
    }

    /** The entries of a report of this node's own devices (robots and doors), as {@link DeviceReport} says. */
    static List<Map<String, Object>> encode(List<ProviderSnapshot> owned) {
        List<Map<String, Object>> all = new ArrayList<>();
        for (ProviderSnapshot p : owned) {
            if (!DeviceKind.ROBOT.label.equals(p.kind()) && !DeviceKind.DOOR.label.equals(p.kind())) {
                continue;
            }
            Map<String, Object> device = new LinkedHashMap<>();
            device.put("id", p.id());
            device.put("kind", p.kind());
            device.put("status", p.status().name());
            if (p.lastPoll() != null) {
                device.put("lastPoll", p.lastPoll().toEpochMilli());
            }
            if (p.reason() != null) {
                device.put("reason", p.reason());
            }
            Map<String, Object> values = new LinkedHashMap<>();
            p.services().forEach((service, resources) -> {
                Map<String, Object> byName = new LinkedHashMap<>();
                resources.forEach((name, v) -> {
                    if (v.value() != null) {
                        byName.put(name, v.value());
                    }
                });
                values.put(service, byName);
            });
            device.put("values", values);
            all.add(device);
        }
        return all;
    }

    private boolean stale(Entry e) {
        return nanoClock.getAsLong() - e.receivedNanos() > freshMillis * 1_000_000L;
    }

    private ProviderSnapshot aged(Entry e) {
        if (!stale(e) || e.snapshot().status() == ResourceStatus.UNREACHABLE) {
            return e.snapshot();
        }
        ProviderSnapshot p = e.snapshot();
        long ago = (nanoClock.getAsLong() - e.receivedNanos()) / 1_000_000L;
        return new ProviderSnapshot(p.id(), p.kind(), ResourceStatus.STALE, p.lastPoll(), "node " + e.node()
                + " has not reported " + p.id() + " for " + ago + " ms", restated(p, ResourceStatus.STALE),
                p.actions());
    }

    private static Map<String, Map<String, ResourceValue>> restated(ProviderSnapshot p, ResourceStatus status) {
        Map<String, Map<String, ResourceValue>> services = new LinkedHashMap<>();
        p.services().forEach((service, resources) -> {
            Map<String, ResourceValue> byName = new TreeMap<>();
            resources.forEach((name, v) -> byName.put(name,
                    new ResourceValue(v.provider(), v.service(), v.resource(), v.value(), v.timestamp(), status)));
            services.put(service, Collections.unmodifiableMap(byName));
        });
        return Collections.unmodifiableMap(services);
    }

    /** @return the entry, or null when the map is not a device entry of a report */
    private static Entry entry(String node, Map<String, Object> device, long receivedNanos) {
        if (device == null || !(device.get("id") instanceof String id) || !ID.matcher(id).matches()
                || !(device.get("kind") instanceof String kindLabel)) {
            return null;
        }
        DeviceKind kind = DeviceKind.ROBOT.label.equals(kindLabel) ? DeviceKind.ROBOT
                : DeviceKind.DOOR.label.equals(kindLabel) ? DeviceKind.DOOR : null;
        if (kind == null || !(device.get("values") instanceof Map<?, ?> values)) {
            return null;
        }
        ResourceStatus status = status(device.get("status"));
        long lastPollMillis = device.get("lastPoll") instanceof Number n ? n.longValue() : 0L;
        Instant lastPoll = lastPollMillis > 0 ? Instant.ofEpochMilli(lastPollMillis) : null;
        Map<String, Map<String, ResourceValue>> services = new TreeMap<>();
        for (Map.Entry<?, ?> s : values.entrySet()) {
            if (!(s.getKey() instanceof String service) || !(s.getValue() instanceof Map<?, ?> resources)) {
                return null;
            }
            Map<String, ResourceValue> byName = new TreeMap<>();
            for (Map.Entry<?, ?> r : resources.entrySet()) {
                if (!(r.getKey() instanceof String name)) {
                    return null;
                }
                byName.put(name, new ResourceValue(id, service, name, r.getValue(), lastPoll, status));
            }
            services.put(service, Collections.unmodifiableMap(byName));
        }
        services.put(FABRIC_SERVICE, Map.of(OWNER_RESOURCE,
                new ResourceValue(id, FABRIC_SERVICE, OWNER_RESOURCE, node, lastPoll, status)));
        Object reason = device.get("reason");
        ProviderSnapshot snapshot = new ProviderSnapshot(id, kind.label, status, lastPoll,
                reason instanceof String text ? text : null, Collections.unmodifiableMap(services), kind.actions);
        return new Entry(node, snapshot, lastPollMillis, receivedNanos);
    }

    private static ResourceStatus status(Object name) {
        if (name instanceof String text) {
            for (ResourceStatus s : ResourceStatus.values()) {
                if (s.name().equals(text)) {
                    return s;
                }
            }
        }
        return ResourceStatus.STALE;
    }
}
