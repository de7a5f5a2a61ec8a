package eu.brain.iot.edge.impl;

import java.net.URI;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * Polls every device of the fleet once per period and turns what changed into model values and events.
 * <p>
 * Threads: one <em>fleet thread</em> owns all of this class's state, the {@link PolledDevice}s and every write to
 * the {@link DeviceStore}, and publishes the events, so none of it needs a lock. The HTTP client's threads only
 * send, receive and parse, then hand the result to the fleet thread. Polls are scheduled at a fixed rate, spread
 * over the period, and never wait for each other's answers: a slow device delays nobody (its next poll is
 * skipped while one is still in flight). A device that keeps failing is reported once, then polled with backoff.
 * <p>
 * Ticks: the fleet thread does not wake for every poll. It wakes once per tick (at most every
 * {@link #MAX_TICK_NANOS}, less for short periods), sends every poll that has come due and handles every answer
 * that came in since the last tick. So a poll goes out up to one tick after its due time and an answer is handled
 * up to one tick after it came, and a fleet of 10,000 robots costs a few hundred wake-ups a second rather than
 * tens of thousands; the HTTP threads hand answers over through a queue without waking the fleet thread.
 */
final class FleetPoller implements AutoCloseable {

    /**
     * What {@link #read} returns for an answer byte for byte equal to the one the device's values came from (a
     * fleet serves the same bytes while nothing changes, robot-sim does): no parsing, no store writes, no events.
     */
    private static final Object UNCHANGED = new Object();

    /** The longest time between two ticks while polls are due or answers are awaited. */
    static final long MAX_TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(5);

    /** A poll due at {@code at}; stale when its device was removed or rescheduled since ({@code round} differs). */
    private record Due(long at, PolledDevice device, int round) implements Comparable<Due> {
        @Override
        public int compareTo(Due o) {
            return Long.compare(at, o.at);
        }
    }

    /** What {@link #read} returns for a poll that never left the edge: every connection stayed busy. */
    private record NotSent(String reason) {
    }

    /** A poll's outcome, handed from an HTTP thread to the fleet thread. */
    private record Completion(PolledDevice device, HttpAnswer answer, Object result) {
    }

    private final ScheduledExecutorService fleet = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "edge-fleet");
        t.setDaemon(true);
        return t;
    });
    private final DeviceStore store;
    private final Outbox outbox;
    private final EdgeLog log;
    private final AnswerParser parser = new AnswerParser();
    private final PollStats stats = new PollStats();
    private final MissionTracker missions;

    /** Written on the fleet thread, read by command senders. */
    private volatile FleetSettings settings;
    private volatile FleetHttpClient client;
    // fleet thread only
    private final Map<String, PolledDevice> devices = new HashMap<>();
    private ScheduledFuture<?> discovery;
    private int discoveryFailures;
    /** Polls to send, earliest first. */
    private final PriorityQueue<Due> due = new PriorityQueue<>();
    /** Polls sent and not handled yet: while there are some, ticks go on to handle their answers. */
    private int pollsInFlight;
    private ScheduledFuture<?> tick;
    private long tickAtNanos;
    private boolean ticking;
    private int notSentSinceWarning;
    private long notSentWarnedMillis;
    /** Answers of polls, from the HTTP threads, handled at the next tick. */
    private final Queue<Completion> completions = new ConcurrentLinkedQueue<>();

    FleetPoller(DeviceStore store, EventSink events, EdgeLog log) {
        this.store = store;
        this.outbox = new Outbox(events, log);
        this.log = log;
        this.missions = new MissionTracker(parser, outbox, log);
    }

    /** Publish an event from any thread: it joins the edge's events on the fleet thread (see {@link Outbox}). */
    void publishFromAnyThread(BrainIoTEvent event) {
        try {
            fleet.execute(() -> outbox.publish(event));
        } catch (java.util.concurrent.RejectedExecutionException closed) {
            log.warn("the edge is stopping: " + event.getClass().getSimpleName() + " not published");
        }
    }

    Outbox outbox() {
        return outbox;
    }

    /** Applies a configuration (the first one, or a new one): devices are added and removed, nothing restarts. */
    void configure(FleetSettings next) {
        fleet.execute(() -> apply(next));
    }

    FleetSettings settings() {
        return settings;
    }

    FleetHttpClient client() {
        return client;
    }

    PollStats stats() {
        return stats;
    }

    private void apply(FleetSettings next) {
        FleetSettings previous = settings;
        if (client == null || !next.sameConnection(previous)) {
            FleetHttpClient old = client;
            client = new FleetHttpClient(next.ioThreads(), next.maxConnections(), next.timeoutMillis());
            if (old != null) {
                old.close();
            }
        }
        settings = next;
        if (previous != null && !previous.baseUrl().equals(next.baseUrl())) {
            setDevices(Map.of()); // every device answers elsewhere now
        }
        cancelDiscovery();
        if (next.discover()) {
            discover();
        } else {
            Map<String, DeviceKind> wanted = new LinkedHashMap<>();
            next.robots().forEach(id -> wanted.put(id, DeviceKind.ROBOT));
            next.doors().forEach(id -> wanted.put(id, DeviceKind.DOOR));
            setDevices(wanted);
        }
    }

    private void discover() {
        FleetSettings s = settings;
        client.get(s.baseUrl()).whenComplete((answer, error) -> {
            Object result;
            try {
                if (error != null) {
                    throw error instanceof DeviceIOException d ? d : new DeviceIOException(String.valueOf(error));
                }
                if (!answer.ok()) {
                    throw new DeviceIOException("HTTP " + answer.status() + ": " + parser.errorText(answer));
                }
                result = parser.inventory(answer.body());
            } catch (Throwable t) {
                result = t.getMessage();
            }
            Object r = result;
            fleet.execute(() -> discovered(s, r));
        });
    }

    private void discovered(FleetSettings asked, Object result) {
        if (asked != settings) {
            return; // configured again meanwhile
        }
        if (result instanceof AnswerParser.Inventory inventory) {
            discoveryFailures = 0;
            Map<String, DeviceKind> wanted = new LinkedHashMap<>();
            inventory.robots().forEach(id -> wanted.put(id, DeviceKind.ROBOT));
            inventory.doors().forEach(id -> wanted.put(id, DeviceKind.DOOR));
            log.info("fleet at " + asked.baseUrl() + ": " + inventory.robots().size() + " robots, "
                    + inventory.doors().size() + " doors");
            setDevices(wanted);
            return;
        }
        discoveryFailures++;
        long delay = backoff(asked, discoveryFailures);
        if (discoveryFailures == 1) {
            log.warn("cannot list the fleet at " + asked.baseUrl() + " (" + result + "); is robot-sim running? "
                    + "Retrying every " + delay + " ms or more, up to backoff.max.ms; or set robots and doors in "
                    + "the configuration " + EdgeConfig.PID);
        }
        discovery = fleet.schedule(this::discover, delay, TimeUnit.MILLISECONDS);
    }

    private void cancelDiscovery() {
        if (discovery != null) {
            discovery.cancel(false);
            discovery = null;
        }
        discoveryFailures = 0;
    }

    private void setDevices(Map<String, DeviceKind> wanted) {
        for (PolledDevice d : new ArrayList<>(devices.values())) {
            if (wanted.get(d.id) != d.kind) {
                devices.remove(d.id);
                d.removed = true; // its entry in the due queue is dropped when it comes up
                store.remove(d.id);
            }
        }
        List<PolledDevice> added = new ArrayList<>();
        wanted.forEach((id, kind) -> {
            if (!devices.containsKey(id)) {
                PolledDevice d = new PolledDevice(id, kind, kind.stateUri(settings.baseUrl(), id));
                devices.put(id, d);
                store.add(id, kind.label, kind.actions);
                added.add(d);
            }
        });
        // Spread the first polls over one period, so that a large fleet is not polled in bursts.
        long period = TimeUnit.MILLISECONDS.toNanos(settings.periodMillis());
        long now = System.nanoTime();
        for (int i = 0; i < added.size(); i++) {
            schedule(added.get(i), now + period * i / added.size());
        }
    }

    /** Puts a device's next poll at {@code atNanos}, replacing the one it had. */
    private void schedule(PolledDevice d, long atNanos) {
        d.dueNanos = atNanos;
        d.round++;
        due.add(new Due(atNanos, d, d.round));
        if (!ticking && (tick == null || atNanos < tickAtNanos)) {
            armTick(atNanos, System.nanoTime());
        }
    }

    private void armTick(long atNanos, long now) {
        if (tick != null) {
            tick.cancel(false);
        }
        tickAtNanos = Math.max(atNanos, now);
        tick = fleet.schedule(this::tick, tickAtNanos - now, TimeUnit.NANOSECONDS);
    }

    private long tickNanos() {
        return Math.max(TimeUnit.MICROSECONDS.toNanos(100),
                Math.min(MAX_TICK_NANOS, TimeUnit.MILLISECONDS.toNanos(settings.periodMillis()) / 20));
    }

    /** On the fleet thread: handles the answers that came, sends the polls that are due, arms the next tick. */
    private void tick() {
        tick = null;
        ticking = true;
        try {
            outbox.flush();
            for (Completion c; (c = completions.poll()) != null; ) {
                pollsInFlight--;
                completed(c.device(), c.answer(), c.result());
            }
            long now = System.nanoTime();
            for (Due head; (head = due.peek()) != null && head.at() <= now; ) {
                due.poll();
                PolledDevice d = head.device();
                if (!d.removed && head.round() == d.round) {
                    poll(d, now);
                }
            }
        } finally {
            ticking = false;
            long now = System.nanoTime();
            long next = Long.MAX_VALUE;
            Due head = due.peek();
            if (head != null) {
                next = head.at();
            }
            if (pollsInFlight > 0 || !completions.isEmpty() || !outbox.isEmpty()) {
                next = Math.min(next, now);
            }
            if (next != Long.MAX_VALUE) {
                armTick(Math.max(next, now + tickNanos()), now); // at most one tick per tick time: batches
            }
        }
    }

    private void poll(PolledDevice d, long now) {
        try {
            FleetSettings s = settings;
            long delay = d.unreachable ? TimeUnit.MILLISECONDS.toNanos(backoff(s, d.failures - s.unreachableAfter() + 1))
                    : TimeUnit.MILLISECONDS.toNanos(s.periodMillis());
            long next = d.dueNanos + delay;
            if (next <= now) {
                next = now + delay; // fell behind (the fleet thread was held up): start a fresh cadence
            }
            schedule(d, next);
            if (d.inFlight) {
                stats.skipped();
                return;
            }
            d.inFlight = true;
            pollsInFlight++;
            stats.sent();
            byte[] previous = d.lastBody; // immutable: the HTTP thread only compares with it
            client.get(d.stateUri).whenComplete((answer, error) -> {
                Object result = read(d, previous, answer, error);
                completions.add(new Completion(d, answer, result)); // handled at the next tick
            });
        } catch (RuntimeException e) {
            // Never let one device's trouble end the fleet thread's schedule of it.
            log.warn("polling " + d.id + " failed unexpectedly: " + e);
        }
    }

    /**
     * On an HTTP thread: the parsed answer, {@link #UNCHANGED} when its bytes are those of the answer the device's
     * current values came from, or a failure's description (a String).
     */
    private Object read(PolledDevice d, byte[] previous, HttpAnswer answer, Throwable error) {
        if (error != null) {
            if (error instanceof DeviceIOException e && e.notSent) {
                return new NotSent(e.getMessage());
            }
            return error instanceof DeviceIOException ? error.getMessage() : String.valueOf(error);
        }
        if (!answer.ok()) {
            return "HTTP " + answer.status() + ": " + parser.errorText(answer);
        }
        if (previous != null && Arrays.equals(previous, answer.body())) {
            return UNCHANGED;
        }
        try {
            return d.kind == DeviceKind.ROBOT ? parser.robot(d.id, answer.body()) : parser.door(d.id, answer.body());
        } catch (DeviceIOException e) {
            return e.getMessage();
        } catch (RuntimeException e) {
            return "unreadable answer: " + e;
        }
    }

    private void completed(PolledDevice d, HttpAnswer answer, Object result) {
        d.inFlight = false;
        if (d.removed) {
            return;
        }
        try {
            if (result instanceof String failure) {
                failed(d, failure);
            } else if (result instanceof NotSent notSent) {
                notSent(d, notSent.reason());
            } else {
                answered(d, answer, result);
            }
        } catch (RuntimeException e) {
            log.warn("handling the answer of " + d.id + " failed unexpectedly: " + e);
        }
    }

    /**
     * The poll never left the edge: every connection stayed busy until the timeout (the edge is overloaded, or
     * the fleet answers too slowly for max.connections). The values are stale, but the device is not counted as
     * failing, so an overloaded edge (say, while a large fleet is first polled on a cold JVM) does not report
     * healthy devices unreachable. One warning a minute for the whole fleet.
     */
    private void notSent(PolledDevice d, String reason) {
        stats.failed();
        d.lastAnsweredSentNanos = -1;
        if (!d.unreachable) {
            store.failed(d.id, ResourceStatus.STALE, reason);
        }
        notSentSinceWarning++;
        long now = System.currentTimeMillis();
        if (now - notSentWarnedMillis >= 60_000) {
            log.warn(notSentSinceWarning + " poll(s) could not be sent (" + reason + "); the edge is overloaded or "
                    + "the fleet slow: the devices are not counted as failing. More max.connections or io.threads may "
                    + "help");
            notSentWarnedMillis = now;
            notSentSinceWarning = 0;
        }
    }

    private void failed(PolledDevice d, String reason) {
        stats.failed();
        d.failures++;
        d.lastAnsweredSentNanos = -1;
        FleetSettings s = settings;
        if (d.unreachable) {
            store.failed(d.id, ResourceStatus.UNREACHABLE, reason);
            return;
        }
        if (d.failures < s.unreachableAfter()) {
            store.failed(d.id, ResourceStatus.STALE, reason);
            warnRateLimited(d, d.kind.label + " " + d.id + ": poll failed: " + reason);
            return;
        }
        d.unreachable = true;
        d.unreachableSinceMillis = System.currentTimeMillis();
        DeviceUnreachable e = new DeviceUnreachable();
        e.deviceId = d.id;
        e.deviceKind = d.kind.label;
        e.reason = reason;
        e.failures = d.failures;
        // the event right after the status, the log line after both: whoever sees UNREACHABLE in the model finds
        // the event (almost) at once, not after a write to a slow log
        store.failed(d.id, ResourceStatus.UNREACHABLE, reason);
        publish(e);
        log.warn(d.kind.label + " " + d.id + " is unreachable after " + d.failures + " failed polls (last: "
                + reason + "); polling it with backoff up to " + s.backoffMaxMillis() + " ms until it answers");
    }

    /** At most one warning a minute per device, saying how many were held back, so a bad device cannot flood. */
    private void warnRateLimited(PolledDevice d, String message) {
        long now = System.currentTimeMillis();
        if (now - d.lastWarnMillis < 60_000) {
            d.warningsSuppressed++;
            return;
        }
        String held = d.warningsSuppressed == 0 ? "" : " (" + d.warningsSuppressed + " similar in the last minute)";
        d.lastWarnMillis = now;
        d.warningsSuppressed = 0;
        log.warn(message + held);
    }

    private void answered(PolledDevice d, HttpAnswer answer, Object parsed) {
        FleetSettings s = settings;
        long sentNanos = answer.sentNanos();
        long interval = d.lastAnsweredSentNanos < 0 || d.unreachable ? -1 : sentNanos - d.lastAnsweredSentNanos;
        stats.answered(interval, TimeUnit.MILLISECONDS.toNanos(s.periodMillis()));
        d.lastAnsweredSentNanos = sentNanos;
        Instant now = Instant.now();
        if (d.unreachable) {
            long down = System.currentTimeMillis() - d.unreachableSinceMillis;
            log.info(d.kind.label + " " + d.id + " answers again after " + down + " ms");
            DeviceRecovered e = new DeviceRecovered();
            e.deviceId = d.id;
            e.deviceKind = d.kind.label;
            e.downMillis = down;
            publish(e);
            // back to the normal cadence now, rather than after the backoff delay already scheduled
            schedule(d, System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(s.periodMillis()));
        }
        d.unreachable = false;
        d.failures = 0;
        store.answered(d.id, now);
        if (parsed == UNCHANGED) {
            return; // the same answer again: the same values, so nothing to set and no event
        }
        d.lastBody = answer.body();
        List<BrainIoTEvent> changes;
        if (parsed instanceof RobotAnswer robot) {
            RobotAnswer before = (RobotAnswer) d.last;
            changes = ChangeDetector.robot(store, before, robot, now);
            d.last = robot;
            changes.forEach(this::publish);
            missions.track(d, before, robot, client, s.baseUrl(), fleet, now);
        } else {
            DoorAnswer door = (DoorAnswer) parsed;
            changes = ChangeDetector.door(store, (DoorAnswer) d.last, door, now);
            d.last = door;
            changes.forEach(this::publish);
        }
    }

    private void publish(BrainIoTEvent event) {
        outbox.publish(event);
    }

    private static long backoff(FleetSettings s, int attempt) {
        long delay = s.periodMillis() << Math.min(Math.max(attempt, 1), 16);
        return Math.min(delay, s.backoffMaxMillis());
    }

    /** The URI of a robot's mission component, for commands and history queries. */
    static URI component(URI base, String robotId, String component, String verb) {
        return base.resolve(robotId + "/robot_local_control/NavigationComponent/" + component + "/" + verb);
    }

    @Override
    public void close() {
        fleet.shutdownNow();
        FleetHttpClient c = client;
        if (c != null) {
            c.close();
        }
    }
}
