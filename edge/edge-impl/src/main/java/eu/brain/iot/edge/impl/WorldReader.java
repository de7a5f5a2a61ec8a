package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * Reads the fleet's world ({@code GET /world}) every {@code world.period.ms} and puts what robots and doors do not
 * tell into the {@link DeviceStore}: one provider per cart ({@code cart1}, ...: {@code position.x}, {@code position.y},
 * {@code cart.carriedBy}) and the map (provider {@value WorldAnswer#WAREHOUSE}: {@code map.width}, {@code map.height},
 * {@code map.rows}, {@code map.name}). The store makes the change, so SSE and the REST API show them like any
 * provider; no bus event is derived (a cart's moves are its robot's {@code CartLifted}/{@code CartPlaced}).
 * <p>
 * Threads: every field belongs to the fleet thread ({@link FleetThread}); the HTTP thread that reads the answer
 * only parses it and hands it back there. One read at a time; the next is scheduled when the last one ended.
 */
final class WorldReader {

    private final FleetThread fleet;
    private final FleetApi api;
    private final DeviceStore store;
    private final EdgeLog log;

    // fleet thread only
    private FleetSettings settings;
    private ScheduledFuture<?> next;
    private final Set<String> known = new HashSet<>();
    private long warnedMillis;

    WorldReader(FleetThread fleet, FleetApi api, DeviceStore store, EdgeLog log) {
        this.fleet = fleet;
        this.api = api;
        this.store = store;
        this.log = log;
    }

    /** Applies a configuration, after the {@link FleetPoller} (the fleet API is configured by then). */
    void configure(FleetSettings s) {
        fleet.run(() -> apply(s), "applying the world's reading period", log);
    }

    private void apply(FleetSettings s) {
        FleetSettings previous = settings;
        settings = s;
        if (next != null) {
            next.cancel(false);
            next = null;
        }
        if (s.worldPeriodMillis() == 0) {
            forgetAll("world.period.ms is 0: the fleet's world is not read");
        } else if (previous != null && !previous.baseUrl().equals(s.baseUrl())) {
            forgetAll("fleet.url changed to " + s.baseUrl()); // another fleet: what was read is no longer true
        }
        if (s.worldPeriodMillis() > 0) {
            read();
        }
    }

    private void read() {
        FleetSettings asked = settings;
        next = null;
        api.world().whenComplete((world, error) -> onFleetThread(() -> {
            if (asked != settings) {
                return; // configured again meanwhile: apply() started a read of its own
            }
            if (error == null) {
                answered(world);
            } else {
                failed(error.getCause() != null ? error.getCause().getMessage() : error.getMessage());
            }
            next = fleet.schedule(this::read, asked.worldPeriodMillis(), TimeUnit.MILLISECONDS);
        }));
    }

    /** Hands work to the fleet thread; once the edge stopped, a read's late answer is of no use to anyone. */
    private void onFleetThread(Runnable task) {
        try {
            fleet.execute(task);
        } catch (java.util.concurrent.RejectedExecutionException stopped) {
            // the edge is closed: nothing to update
        }
    }

    private void answered(WorldAnswer world) {
        Instant now = Instant.now();
        Set<String> seen = new HashSet<>();
        put(world.map(), DeviceKind.WAREHOUSE, now);
        seen.add(world.map().id());
        for (WorldAnswer.Cart c : world.carts()) {
            put(c, DeviceKind.CART, now);
            seen.add(c.id());
        }
        for (String id : Set.copyOf(known)) {
            if (!seen.contains(id)) {
                known.remove(id);
                store.remove(id, "not in the fleet's world any more");
            }
        }
    }

    private void put(DeviceAnswer answer, DeviceKind kind, Instant now) {
        if (known.add(answer.id())) {
            store.add(answer.id(), kind);
        }
        store.update(answer.id(), answer, now);
    }

    private void failed(String reason) {
        known.forEach(id -> store.stale(id, reason));
        long now = System.currentTimeMillis();
        if (now - warnedMillis >= 60_000) {
            warnedMillis = now;
            log.warn("cannot read the fleet's world at " + settings.baseUrl() + "world (" + reason + "); carts and "
                    + "map keep their last values, marked STALE; retrying every " + settings.worldPeriodMillis()
                    + " ms (world.period.ms; 0 stops reading it)");
        }
    }

    private void forgetAll(String reason) {
        known.forEach(id -> store.remove(id, reason));
        known.clear();
    }
}
