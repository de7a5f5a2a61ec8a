package eu.brain.iot.dashboard;

import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.metatype.annotations.Designate;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.federation.monitoring.api.FabricMonitor;

/**
 * The dashboard's state and its event streams. Follows the edge's device model (its listener, never the bus's
 * position and door events: see {@link ConsumedTypes}), takes the bus events {@link BusListener} hands it, reads the
 * fabric's statistics, and every {@code flush.ms} sends what changed to every page as one SSE event with an id.
 * <p>
 * Threads: the edge's thread and the bus's workers only add {@link Change}s to a queue (never waiting); the one
 * dashboard thread ({@code executor}) owns {@link Devices}, {@link Activity}, {@link EventLog} and the list of
 * streams, applies the changes, builds snapshots and events, and writes to the streams (which never block). A page's
 * request hands its work to that thread and waits for the answer.
 */
@Component(service = Hub.class, configurationPid = DashboardConfig.PID)
@Designate(ocd = DashboardConfig.class)
public final class Hub {

    /** Changes waiting beyond this mean the dashboard thread cannot keep up: it then reloads the model whole. */
    private static final int MAX_WAITING = 500_000;
    private static final long RECONCILE_MS = 5_000;

    private final DeviceModel model;
    private final Fabric fabric;
    private final Logger log;
    private final DashboardConfig config;
    private final ScheduledExecutorService executor = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "dashboard");
        t.setDaemon(true);
        return t;
    });
    private final ConcurrentLinkedQueue<Change> changes = new ConcurrentLinkedQueue<>();
    private final AtomicInteger waiting = new AtomicInteger();
    private final DeviceModel.Subscription subscription;

    // owned by the dashboard thread
    private final Activity activity;
    private final Devices devices;
    private final EventLog events;
    private final Set<SseStream> streams = new HashSet<>();
    /** The fabric's last reading, as JSON (DTOs have no equals: compared as text). */
    private String fabricNow = "{}";
    private boolean fabricChanged;
    private long nextReconcile;
    private final StreamLimit streamLimit;
    /**
     * The fabric's monitor while the node has a fabric configuration: dynamic, so that a node joining or leaving a
     * fabric does not restart the dashboard (and close every page's stream). Set by SCR on any thread.
     */
    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    private volatile FabricMonitor fabricMonitor;

    @Activate
    public Hub(@Reference DeviceModel model,
            @Reference(cardinality = ReferenceCardinality.OPTIONAL, policyOption = ReferencePolicyOption.GREEDY)
            EventBusStatistics bus,
            @Reference(cardinality = ReferenceCardinality.OPTIONAL, policyOption = ReferencePolicyOption.GREEDY)
            BundleInstaller installer,
            @Reference(cardinality = ReferenceCardinality.OPTIONAL, policyOption = ReferencePolicyOption.GREEDY)
            BehaviourManagerStatistics bms,
            @Reference(cardinality = ReferenceCardinality.OPTIONAL, policyOption = ReferencePolicyOption.GREEDY)
            PollMonitor poll,
            DashboardConfig config, @Reference(service = LoggerFactory.class) Logger log) {
        this.model = model;
        this.config = check(config);
        this.log = log;
        this.streamLimit = new StreamLimit(config.max_streams(), log);
        this.fabric = new Fabric(bus, installer, bms, poll, () -> fabricMonitor);
        this.activity = new Activity(config.decisions());
        this.devices = new Devices(activity);
        this.events = new EventLog(Long.toString(System.currentTimeMillis(), 36), config.replay_events());
        // subscribe before reading the model: nothing that changes in between is missed
        this.subscription = model.subscribe(null, null, v -> offer(new Change.Resource(v)));
        executor.execute(this::reload);
        executor.scheduleWithFixedDelay(this::flush, config.flush_ms(), config.flush_ms(), TimeUnit.MILLISECONDS);
        executor.scheduleAtFixedRate(this::readFabric, 0, config.fabric_period_ms(), TimeUnit.MILLISECONDS);
        executor.scheduleAtFixedRate(this::heartbeat, config.heartbeat_ms(), config.heartbeat_ms(),
                TimeUnit.MILLISECONDS);
    }

    private static DashboardConfig check(DashboardConfig c) {
        positive("flush.ms", c.flush_ms());
        positive("fabric.period.ms", c.fabric_period_ms());
        positive("replay.events", c.replay_events());
        positive("client.queue.capacity", c.client_queue_capacity());
        positive("heartbeat.ms", c.heartbeat_ms());
        positive("max.streams", c.max_streams());
        positive("decisions", c.decisions());
        return c;
    }

    private static void positive(String property, long value) {
        if (value <= 0) {
            throw new IllegalArgumentException("configuration " + DashboardConfig.PID + ": " + property
                    + " must be positive, found " + value);
        }
    }

    @Deactivate
    void deactivate() {
        subscription.close();
        CompletableFuture<Void> closed = CompletableFuture.runAsync(() -> List.copyOf(streams).forEach(SseStream::close),
                executor);
        closed.orTimeout(2, TimeUnit.SECONDS).exceptionally(e -> null).join();
        executor.shutdownNow();
    }

    /** Hands a change to the dashboard thread; called from any thread, never waits. */
    void offer(Change change) {
        if (waiting.incrementAndGet() > MAX_WAITING) {
            return; // flush() sees the overflow and reloads
        }
        changes.add(change);
    }

    /** The whole state now, as JSON, with the id of the last event it includes. */
    CompletableFuture<String> snapshot() {
        return CompletableFuture.supplyAsync(() -> Json.write(state()), executor);
    }

    /**
     * Starts a stream: the events after {@code lastEventId} when they can be replayed, else a snapshot first; then
     * every new event.
     */
    void attach(SseStream stream, String lastEventId) {
        try {
            executor.execute(() -> {
                stream.start();
                events.after(lastEventId).ifPresentOrElse(missed -> missed.forEach(f -> stream.send(f.text())),
                        () -> stream.send(events.snapshot(Json.write(state()))));
                streams.add(stream);
            });
        } catch (RejectedExecutionException e) {
            stream.close(); // the dashboard is stopping
        }
    }

    /** Forgets a stream that ended; called from any thread. */
    void detach(SseStream stream) {
        try {
            executor.execute(() -> streams.remove(stream));
        } catch (RejectedExecutionException e) {
            // stopping: the list goes with the executor
        }
    }

    private Map<String, Object> state() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("eventId", events.lastId());
        m.put("serverTime", System.currentTimeMillis());
        m.put("devices", devices.all());
        m.put("counters", activity.counters());
        m.put("decisions", activity.decisions());
        m.put("fabric", Json.raw(fabricNow));
        m.put("consumed", ConsumedTypes.CONSUMED);
        return m;
    }

    /** Reads the model whole: every provider is sent whole in the next event. */
    private void reload() {
        reconcile(true);
    }

    /**
     * Drops the providers the model no longer has (a fleet reconfigured) and loads those the listener has not told
     * of; with {@code all}, loads every provider again.
     */
    private void reconcile(boolean all) {
        Set<String> ids = new HashSet<>();
        for (ProviderSnapshot p : model.providers()) {
            if (all || !devices.ids().contains(p.id())) {
                devices.load(p);
            }
            ids.add(p.id());
        }
        devices.retain(ids);
        nextReconcile = System.currentTimeMillis() + RECONCILE_MS;
    }

    private void readFabric() {
        try {
            String now = Json.write(fabric.read());
            if (!now.equals(fabricNow)) {
                fabricNow = now;
                fabricChanged = true;
            }
        } catch (RuntimeException e) {
            log.warn("dashboard: could not read the fabric's statistics: " + e);
        }
    }

    private void flush() {
        try {
            apply();
            if (System.currentTimeMillis() >= nextReconcile) {
                reconcile(false);
            }
            publish();
        } catch (RuntimeException e) {
            log.error("dashboard: could not send the latest changes", e); // the next flush tries again
        }
    }

    private void apply() {
        int n = waiting.get();
        if (n > MAX_WAITING) {
            log.warn("dashboard: " + n + " changes waited; the device model is read again whole");
            changes.clear();
            waiting.set(0);
            reload();
            return;
        }
        Set<String> reloads = new HashSet<>();
        for (int i = 0; i < n; i++) {
            Change c = changes.poll();
            if (c == null) {
                break;
            }
            waiting.decrementAndGet();
            c.apply(devices, activity, reloads);
        }
        reloads.forEach(id -> model.provider(id).ifPresent(devices::load));
    }

    private void publish() {
        Map<String, Long> counters = activity.takeCounters();
        List<Map<String, Object>> decisions = activity.takeDecisions();
        if (!devices.hasChanges() && counters == null && decisions.isEmpty() && !fabricChanged) {
            return;
        }
        Map<String, Object> delta = new LinkedHashMap<>();
        delta.put("serverTime", System.currentTimeMillis());
        delta.put("devices", devices.takeChanged());
        delta.put("removed", devices.takeRemoved());
        if (counters != null) {
            delta.put("counters", counters);
        }
        if (!decisions.isEmpty()) {
            delta.put("decisions", decisions);
        }
        if (fabricChanged) {
            delta.put("fabric", Json.raw(fabricNow));
            fabricChanged = false;
        }
        String frame = events.append("delta", Json.write(delta)).text();
        List.copyOf(streams).forEach(s -> s.send(frame));
    }

    private void heartbeat() {
        List.copyOf(streams).forEach(s -> s.send(": heartbeat\n\n"));
    }

    /** The cap on open streams: a stream acquires it before it starts and releases it when it ends. */
    StreamLimit streamLimit() {
        return streamLimit;
    }

    int clientQueueCapacity() {
        return config.client_queue_capacity();
    }
}
