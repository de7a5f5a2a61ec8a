package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

/**
 * Schedules the polls of every device of the fleet, once per period, and hands each poll's result to the
 * {@link DeviceStore}, where the change happens (and from which the SSE updates and the bus events leave).
 * <p>
 * Threads: one <em>fleet thread</em> owns all of this class's state and the {@link PolledDevice}s, so none of it
 * needs a lock. The {@link FleetApi}'s HTTP threads only send, receive and parse, then hand a typed
 * {@link PollResult} to the fleet thread. Polls are scheduled at a fixed rate, spread
 * over the period, and never wait for each other's answers: a slow device delays nobody (its next poll is
 * skipped while one is still in flight). A device that keeps failing is reported once, then polled with backoff.
 * <p>
 * Ticks: the fleet thread does not wake for every poll. It wakes once per tick (at most every
 * {@link #MAX_TICK_NANOS}, less for short periods), sends every poll that has come due and handles every answer
 * that came in since the last tick. So a poll goes out up to one tick after its due time and an answer is handled
 * up to one tick after it came, and a fleet of 10,000 robots costs a few hundred wake-ups a second rather than
 * tens of thousands; the HTTP threads hand answers over through a queue without waking the fleet thread. Each
 * tick first sends what waits in the {@link Outbox} (events the bus refused), and ticks go on while anything waits
 * there: the bus is offered events, never waited for.
 */
final class FleetPoller implements AutoCloseable, PollResult.Handler<PolledDevice> {

    /** The longest time between two ticks while polls are due or answers are awaited. */
    static final long MAX_TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(5);

    /** A poll due at {@code at}; stale when its device was removed or rescheduled since ({@code round} differs). */
    private record Due(long at, PolledDevice device, int round) implements Comparable<Due> {
        @Override
        public int compareTo(Due o) {
            return Long.compare(at, o.at);
        }
    }

    /** A poll's outcome, handed from an HTTP thread to the fleet thread. */
    private record Completion(PolledDevice device, PollResult result) {
    }

    private final FleetThread fleet;
    private final FleetApi api;
    private final DeviceStore store;
    private final Outbox outbox;
    private final EdgeLog log;
    private final Ownership ownership;
    private final PollStats stats = new PollStats();

    // fleet thread only
    private FleetSettings settings;
    private final Map<String, PolledDevice> devices = new HashMap<>();
    /**
     * Devices of the model that the fleet at a new {@code fleet.url} has not confirmed yet: not polled, their health
     * at the old fleet kept for their successor (see {@link #unlist}). Empty outside that transition.
     */
    private final Map<String, PolledDevice> unlisted = new HashMap<>();
    /**
     * The fleet's devices as last learnt (configuration or inventory), owned or not, and why one that leaves it is
     * removed; {@code fleetKnown} false while the inventory of the fleet in force has not answered yet.
     */
    private Map<String, DeviceKind> fleetDevices = Map.of();
    private String fleetRemoval;
    private boolean fleetKnown;
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

    FleetPoller(FleetThread fleet, FleetApi api, DeviceStore store, Outbox outbox, EdgeLog log, Ownership ownership) {
        this.ownership = ownership;
        this.fleet = fleet;
        this.api = api;
        this.store = store;
        this.outbox = outbox;
        this.log = log;
    }

    /** Applies a configuration (the first one, or a new one): devices are added and removed, nothing restarts. */
    void configure(FleetSettings next) {
        fleet.execute(() -> {
            try {
                apply(next);
            } catch (RuntimeException e) {
                // the executor would keep it in a future no one reads: the configuration would fail without a word
                log.warn("applying the configuration " + EdgeConfig.PID + " failed: " + e);
            }
        });
    }

    PollStats stats() {
        return stats;
    }

    private void apply(FleetSettings next) {
        FleetSettings previous = settings;
        api.configure(next);
        settings = next;
        ownership.share(next.share());
        fleetKnown = false;
        cancelDiscovery();
        if (previous != null && !previous.baseUrl().equals(next.baseUrl())) {
            unlist(next); // every device answers elsewhere now, if the new fleet has it
        }
        if (next.discover()) {
            discover();
        } else {
            Map<String, DeviceKind> wanted = new LinkedHashMap<>();
            next.robots().forEach(id -> wanted.put(id, DeviceKind.ROBOT));
            next.doors().forEach(id -> wanted.put(id, DeviceKind.DOOR));
            fleetIs(wanted, "not in the configuration " + EdgeConfig.PID + " any more (robots, doors)");
        }
    }

    /**
     * {@code fleet.url} changed. The devices keep their ids in the model, since the usual case is the same robots at
     * another address (a restarted simulator, a proxy): dropping and re-creating them, as the edge once did, told a
     * behaviour that had heard {@code DeviceUnreachable} neither a recovery nor a removal, so it waited forever.
     * Each stops being polled at the old fleet and waits here until the new fleet confirms it ({@link #setDevices}):
     * at once when the configuration names the devices, when the fleet's inventory ({@code GET /}) answers
     * otherwise. Meanwhile the model holds no values for it (they were the old fleet's) and keeps an unreachable
     * device {@code UNREACHABLE}, the others {@code STALE}, with this reason; one the new fleet does not have is
     * removed then, with a {@code DeviceRemoved} event. A fleet that never answers its inventory leaves them so,
     * marked and explained, rather than live.
     */
    private void unlist(FleetSettings next) {
        String reason = "fleet.url changed to " + next.baseUrl()
                + (next.discover() ? ": waiting for its inventory (GET /)" : ": not polled there yet");
        for (PolledDevice d : devices.values()) {
            d.removed = true; // an answer still on its way from the old fleet is dropped, its due poll too
            unlisted.put(d.id, d);
        }
        devices.clear();
        unlisted.keySet().forEach(id -> store.moved(id, reason));
        if (!unlisted.isEmpty()) {
            log.info("fleet.url changed to " + next.baseUrl() + ": " + unlisted.size() + " device(s) kept under "
                    + "their ids, polled there " + (next.discover() ? "once its inventory lists them" : "from now on"));
        }
    }

    private void discover() {
        FleetSettings asked = settings;
        api.inventory().whenComplete((inventory, error) -> fleet.execute(() -> {
            if (asked != settings) {
                return; // configured again meanwhile
            }
            if (error == null) {
                discovered(asked, inventory);
            } else {
                notDiscovered(asked, error.getCause() != null ? error.getCause().getMessage() : error.getMessage());
            }
        }));
    }

    private void discovered(FleetSettings asked, AnswerParser.Inventory inventory) {
        discoveryFailures = 0;
        Map<String, DeviceKind> wanted = new LinkedHashMap<>();
        inventory.robots().forEach(id -> wanted.put(id, DeviceKind.ROBOT));
        inventory.doors().forEach(id -> wanted.put(id, DeviceKind.DOOR));
        log.info("fleet at " + asked.baseUrl() + ": " + inventory.robots().size() + " robots, "
                + inventory.doors().size() + " doors");
        fleetIs(wanted, "not in the fleet at " + asked.baseUrl() + " (GET / lists " + inventory.robots().size()
                + " robots, " + inventory.doors().size() + " doors)");
    }

    private void notDiscovered(FleetSettings asked, String problem) {
        discoveryFailures++;
        long delay = backoff(asked, discoveryFailures);
        if (discoveryFailures == 1) {
            log.warn("cannot list the fleet at " + asked.baseUrl() + " (" + problem + "); is robot-sim running? "
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

    /**
     * The fleet has these devices: this node polls those it owns ({@link Ownership}); a device that left the fleet is
     * removed with {@code removal} as the reason, one this node does not own (any more) as not owned.
     */
    private void fleetIs(Map<String, DeviceKind> wanted, String removal) {
        fleetDevices = Map.copyOf(wanted);
        fleetRemoval = removal;
        fleetKnown = true;
        ownership.fleet(wanted);
        setDevices(ownership.ownedOf(wanted), id -> wanted.containsKey(id) ? notOwned() : removal, false);
    }

    /**
     * Ownership changed at run time (a device taken or released, on any thread): on the fleet thread, the devices
     * taken are polled at once, the ones released leave the model. While the fleet's inventory is awaited, its
     * answer applies the change.
     */
    void ownershipChanged() {
        fleet.run(() -> {
            if (settings == null || !fleetKnown) {
                return;
            }
            try {
                setDevices(ownership.ownedOf(fleetDevices),
                        id -> fleetDevices.containsKey(id) ? notOwned() : fleetRemoval, true);
            } catch (RuntimeException e) {
                log.warn("applying a change of ownership failed: " + e);
            }
        }, "a change of the devices this node owns", log);
    }

    private String notOwned() {
        return "not owned by node " + ownership.nodeName() + " (its share " + ownership.shareRule()
                + ", less what it released, plus what it took)";
    }

    /**
     * Polls these devices from now on: the others leave the model (with {@code removal}'s reason for each), new ones
     * enter it, unlisted ones ({@link #unlist}) are polled at the new fleet URL, in the model all along.
     *
     * @param atOnce poll the new ones now (taken over: a behaviour waits for them); else spread over one period
     */
    private void setDevices(Map<String, DeviceKind> wanted, Function<String, String> removal, boolean atOnce) {
        Map<String, List<String>> removed = new LinkedHashMap<>();
        for (Map<String, PolledDevice> known : List.of(devices, unlisted)) {
            for (PolledDevice d : new ArrayList<>(known.values())) {
                if (wanted.get(d.id) != d.kind) {
                    known.remove(d.id);
                    d.removed = true; // its entry in the due queue is dropped when it comes up
                    String reason = removal.apply(d.id);
                    store.remove(d.id, reason);
                    removed.computeIfAbsent(reason, r -> new ArrayList<>()).add(d.id);
                }
            }
        }
        removed.forEach((reason, ids) -> log.info(ids.size() + " device(s) removed, " + reason + ": "
                + (ids.size() <= 10 ? ids : ids.subList(0, 10) + " and more")));
        List<PolledDevice> added = new ArrayList<>();
        wanted.forEach((id, kind) -> {
            if (!devices.containsKey(id)) {
                PolledDevice before = unlisted.remove(id);
                PolledDevice d;
                if (before != null) {
                    d = before.successor(api.stateUri(id, kind), settings.unreachableAfter()); // in the model still
                } else {
                    d = new PolledDevice(id, kind, api.stateUri(id, kind));
                    store.add(id, kind);
                }
                devices.put(id, d);
                added.add(d);
            }
        });
        // Spread the first polls over one period, so that a large fleet is not polled in bursts; devices taken
        // over are polled at once (a behaviour waits to hear where they are).
        long period = atOnce ? 0 : TimeUnit.MILLISECONDS.toNanos(settings.periodMillis());
        long now = System.nanoTime();
        for (int i = 0; i < added.size(); i++) {
            schedule(added.get(i), now + period * i / added.size());
        }
        if (atOnce && !added.isEmpty()) {
            log.info(added.size() + " device(s) taken over by node " + ownership.nodeName() + ", polled now: "
                    + (added.size() <= 10 ? added.stream().map(d -> d.id).toList()
                    : added.subList(0, 10).stream().map(d -> d.id).toList() + " and more"));
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
                completed(c.device(), c.result());
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
            // lastBody is immutable: the HTTP thread only compares with it
            api.poll(d.id, d.kind, d.stateUri, d.lastBody,
                    result -> completions.add(new Completion(d, result))); // handled at the next tick
        } catch (RuntimeException e) {
            // Never let one device's trouble end the fleet thread's schedule of it.
            log.warn("polling " + d.id + " failed unexpectedly: " + e);
        }
    }

    private void completed(PolledDevice d, PollResult result) {
        d.inFlight = false;
        if (d.removed) {
            return;
        }
        try {
            result.handle(d, this);
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
    @Override
    public void notSent(PolledDevice d, PollResult.NotSent notSent) {
        String reason = notSent.reason();
        stats.failed();
        d.lastAnsweredSentNanos = -1;
        if (!d.unreachable) {
            store.stale(d.id, reason);
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

    @Override
    public void failed(PolledDevice d, PollResult.Failed failure) {
        String reason = failure.reason();
        stats.failed();
        d.failures++;
        d.lastAnsweredSentNanos = -1;
        FleetSettings s = settings;
        if (d.unreachable) {
            store.unreachable(d.id, reason, d.failures);
            return;
        }
        if (d.failures < s.unreachableAfter()) {
            store.stale(d.id, reason);
            warnRateLimited(d, d.kind.label + " " + d.id + ": poll failed: " + reason);
            return;
        }
        d.unreachable = true;
        d.unreachableSinceMillis = System.currentTimeMillis();
        // the store tells the status and the event (DeviceUnreachable) first, the log line comes after both:
        // whoever sees UNREACHABLE in the model finds the event (almost) at once, not after a write to a slow log
        store.unreachable(d.id, reason, d.failures);
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

    @Override
    public void answered(PolledDevice d, PollResult.Answered answer) {
        Instant now = answeredAt(d, answer.sentNanos());
        d.lastBody = answer.body();
        store.update(d.id, answer.answer(), now);
    }

    @Override
    public void unchanged(PolledDevice d, PollResult.Unchanged unchanged) {
        // the same answer again: the same values, so nothing to set and no event
        store.unchanged(d.id, answeredAt(d, unchanged.sentNanos()));
    }

    /** Counts an answered poll and brings a device that was unreachable back to the normal cadence. */
    private Instant answeredAt(PolledDevice d, long sentNanos) {
        FleetSettings s = settings;
        long interval = d.lastAnsweredSentNanos < 0 || d.unreachable ? -1 : sentNanos - d.lastAnsweredSentNanos;
        stats.answered(interval, TimeUnit.MILLISECONDS.toNanos(s.periodMillis()));
        d.lastAnsweredSentNanos = sentNanos;
        if (d.unreachable) {
            long down = System.currentTimeMillis() - d.unreachableSinceMillis;
            log.info(d.kind.label + " " + d.id + " answers again after " + down + " ms");
            // back to the normal cadence now, rather than after the backoff delay already scheduled
            schedule(d, System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(s.periodMillis()));
        }
        d.unreachable = false;
        d.failures = 0;
        return Instant.now();
    }

    private static long backoff(FleetSettings s, int attempt) {
        long delay = s.periodMillis() << Math.min(Math.max(attempt, 1), 16);
        return Math.min(delay, s.backoffMaxMillis());
    }

    @Override
    public void close() {
        fleet.shutdown();
    }
}
