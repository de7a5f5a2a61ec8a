package eu.brain.iot.edge.impl;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;

import eu.brain.iot.edge.model.api.DeviceOwnership;

/**
 * Which devices this node owns: its configured {@link Share}, plus the devices taken and less the devices released at
 * run time ({@link DeviceOwnership}, called by a lease manager on any thread). A new share in the configuration
 * starts afresh (what was taken or released before is forgotten); another configuration keeps them.
 * <p>
 * Threads: every field is guarded by this object's lock; the fleet thread reads {@link #owns} and writes
 * {@link #fleet}; callers of {@link #take} and {@link #release} are any threads. The listener (the poller, which
 * re-applies the device set on its fleet thread) is called after the lock is released.
 */
final class Ownership implements DeviceOwnership {

    private static final Pattern ID = Pattern.compile("[A-Za-z0-9_.-]+");

    private final String nodeName;
    private Runnable listener = () -> { };
    private Share share = Share.EVERY_DEVICE;
    private final Set<String> taken = new LinkedHashSet<>();
    private final Set<String> released = new LinkedHashSet<>();
    /** The fleet's devices as the edge last learnt them (inventory or configuration). */
    private Map<String, DeviceKind> fleet = Map.of();

    Ownership(String nodeName) {
        this.nodeName = nodeName;
    }

    /** Who to tell when ownership changed at run time (the poller). */
    synchronized void listener(Runnable changed) {
        this.listener = changed;
    }

    /** A share from the configuration; a different one forgets what was taken and released. */
    synchronized void share(Share next) {
        if (!next.equals(share)) {
            share = next;
            taken.clear();
            released.clear();
        }
    }

    /** The configured share's rule. */
    synchronized Share shareRule() {
        return share;
    }

    /** The fleet's devices, as the edge learnt them (on the fleet thread). */
    synchronized void fleet(Map<String, DeviceKind> devices) {
        fleet = Map.copyOf(devices);
    }

    /** Whether this node owns the device of this kind. */
    synchronized boolean owns(String id, DeviceKind kind) {
        return taken.contains(id) || !share.leased() && !released.contains(id) && share.holds(id, kind);
    }

    /** Of these devices of the fleet, the ones this node owns, in their order. */
    synchronized Map<String, DeviceKind> ownedOf(Map<String, DeviceKind> devices) {
        Map<String, DeviceKind> mine = new LinkedHashMap<>();
        devices.forEach((id, kind) -> {
            if (owns(id, kind)) {
                mine.put(id, kind);
            }
        });
        return mine;
    }

    @Override
    public String nodeName() {
        return nodeName;
    }

    @Override
    public synchronized Set<String> owned() {
        return Collections.unmodifiableSet(new TreeSet<>(ownedOf(fleet).keySet()));
    }

    @Override
    public synchronized Set<String> share() {
        Set<String> mine = new TreeSet<>();
        fleet.forEach((id, kind) -> {
            if (share.holds(id, kind)) {
                mine.add(id);
            }
        });
        return Collections.unmodifiableSet(mine);
    }

    @Override
    public synchronized Set<String> fleet() {
        return Collections.unmodifiableSet(new TreeSet<>(fleet.keySet()));
    }

    @Override
    public synchronized boolean owns(String deviceId) {
        DeviceKind kind = fleet.get(deviceId);
        return taken.contains(deviceId) || kind != null && owns(deviceId, kind);
    }

    @Override
    public Set<String> take(Set<String> deviceIds) {
        Set<String> changed = new TreeSet<>();
        Runnable tell;
        synchronized (this) {
            for (String id : checked(deviceIds)) {
                if (!owns(id)) {
                    changed.add(id);
                }
                released.remove(id);
                taken.add(id);
            }
            tell = listener;
        }
        if (!changed.isEmpty()) {
            tell.run();
        }
        return Collections.unmodifiableSet(changed);
    }

    @Override
    public Set<String> release(Set<String> deviceIds) {
        Set<String> changed = new TreeSet<>();
        Runnable tell;
        synchronized (this) {
            for (String id : checked(deviceIds)) {
                if (owns(id)) {
                    changed.add(id);
                }
                taken.remove(id);
                released.add(id);
            }
            tell = listener;
        }
        if (!changed.isEmpty()) {
            tell.run();
        }
        return Collections.unmodifiableSet(changed);
    }

    private static Set<String> checked(Set<String> ids) {
        if (ids == null) {
            throw new IllegalArgumentException("device ids must be a set of ids, found null");
        }
        for (String id : ids) {
            if (id == null || !ID.matcher(id).matches()) {
                throw new IllegalArgumentException("'" + id + "' is no device id: letters, digits, '_', '.' or '-' "
                        + "(e.g. robot3, door1)");
            }
        }
        return ids;
    }
}
