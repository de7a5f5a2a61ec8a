package eu.brain.iot.bms.impl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import org.osgi.service.log.Logger;
import org.osgi.util.promise.Promise;
import org.osgi.util.promise.Promises;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bms.impl.TypeState.Installed;
import eu.brain.iot.bms.impl.TypeState.Installing;
import eu.brain.iot.bms.impl.TypeState.Rest;
import eu.brain.iot.bms.impl.TypeState.Resting;
import eu.brain.iot.bms.impl.TypeState.RetryWait;
import eu.brain.iot.bms.impl.TypeState.Searching;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.eventing.spi.HeldEvents;
import eu.brain.iot.eventing.spi.HeldType;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy.Disposition;

/**
 * The Behaviour Management Service's core, free of OSGi wiring so that it is unit-tested with virtual time.
 * <p>
 * Two kinds of thread: the bus calls {@link #unhandled} on publishers' threads, and it answers from a map look-up
 * ({@link #states}); only the first event of a type (or the first after a resting period) asks the installer's
 * {@code find}, which a local installer answers from memory with a resolved promise. Everything after that (install
 * requests, their answers, retries, deadlines, giving up on held events, alerts) runs on the BMS's own thread
 * ({@link Scheduler}).
 * <p>
 * A behaviour whose bundle stops or is uninstalled outside the installer is brought back without waiting for an
 * event by {@link Revivals}, which shares the install requests in flight ({@link InstallJobs}) with the event types.
 * <p>
 * Ownership: {@link #states} is shared; each entry is replaced as a whole with {@code replace(type, old, new)}
 * (see {@link TypeState}). {@link #jobs}, {@link #revivals} and {@link #loggedNotFound} belong to the BMS's thread.
 * {@link #settings} is volatile, replaced by {@link #reconfigure}. {@link #searchedTypes} is thread-safe.
 */
final class BehaviourManager {

    private final BundleInstaller installer;
    private final HeldEvents held;
    private final Scheduler scheduler;
    private final Alerts alerts;
    private final Logger log;
    private final ManagerCountersImpl counters;
    private final History history;
    private volatile Settings settings;

    private final ConcurrentHashMap<String, TypeState> states = new ConcurrentHashMap<>();
    private final SearchedTypes searchedTypes = new SearchedTypes();
    /** In-flight install requests by behaviour: types needing the same one, and its revival, share it. */
    private final InstallJobs jobs;
    private final Revivals revivals;
    private final Set<String> loggedNotFound = new HashSet<>();

    /** @param frameworkStopping whether the framework is shutting down: then no behaviour is brought back */
    BehaviourManager(BundleInstaller installer, HeldEvents held, Scheduler scheduler, Alerts alerts, Logger log,
            ManagerCountersImpl counters, Settings settings, BooleanSupplier frameworkStopping) {
        this.installer = installer;
        this.held = held;
        this.scheduler = scheduler;
        this.alerts = alerts;
        this.log = log;
        this.counters = counters;
        this.settings = settings;
        this.history = new History(settings.historySize());
        this.jobs = new InstallJobs(installer, scheduler);
        this.revivals = new Revivals(installer, jobs, scheduler, alerts, log, counters, history, () -> this.settings,
                frameworkStopping, this::answered);
    }

    /** Start the periodic sweep (deadlines, held events nothing waits for). */
    void start() {
        scheduler.every(settings.sweepIntervalMs(), this::sweep);
    }

    void reconfigure(Settings newSettings) {
        settings = newSettings;
        history.resize(newSettings.historySize());
    }

    int maxHeldEvents() {
        return settings.maxHeldEvents();
    }

    // ---------------------------------------------------------------- publishers' threads

    /** The policy's answer (see {@code UnhandledEventPolicy.unhandled}); never blocks; see {@link #search}. */
    Disposition unhandled(String eventType, List<String> typeHierarchy, Supplier<Map<String, Object>> fields) {
        for (String type : typeHierarchy) {
            if (Alerts.TYPES.contains(type)) {
                return Disposition.LAST_RESORT; // our own alerts: never searched for
            }
        }
        counters.unhandled.increment();
        if (settings.ignored(eventType)) {
            return Disposition.LAST_RESORT;
        }
        long now = scheduler.now();
        while (true) {
            TypeState state = states.get(eventType);
            Disposition disposition = state == null ? null : state.disposition(now);
            if (disposition == null) {
                List<String> searched = typeHierarchy.isEmpty() ? List.of(eventType) : List.copyOf(typeHierarchy);
                searchedTypes.started(eventType, searched, fields);
                Searching searching = new Searching(searched, now, 1);
                boolean won = state == null ? states.putIfAbsent(eventType, searching) == null
                        : states.replace(eventType, state, searching);
                if (!won) {
                    continue; // another publisher started the episode: follow it
                }
                disposition = search(eventType, searching);
            }
            if (disposition == Disposition.HOLD) {
                counters.held.increment();
            }
            return disposition;
        }
    }

    /**
     * Ask the installer for candidates, with the fields of the episode's first event (an installer spanning nodes
     * prefers the node that owns the device it names). A resolved answer is used at once (a miss answers LAST_RESORT to this very
     * event: consumers of last resort, else counted as unhandled); otherwise the events are held until the answer
     * arrives on the BMS's thread. Runs on a publisher's thread or on the BMS's.
     */
    private Disposition search(String eventType, Searching searching) {
        counters.searches.increment();
        Promise<List<BehaviourCandidate>> found;
        try {
            found = installer.find(searching.searched(), searchedTypes.firstEvent(eventType));
        } catch (RuntimeException e) {
            found = Promises.failed(e);
        }
        if (found.isDone() && Answers.failure(found) == null) {
            List<BehaviourCandidate> candidates = Answers.value(found);
            if (candidates == null || candidates.isEmpty()) {
                Resting rest = resting(searching, Rest.NOT_FOUND, null, "no repository has a behaviour that "
                        + "consumes it (searched " + searching.searched() + ")");
                rest.unhandled().increment(); // this event
                if (states.replace(eventType, searching, rest)) {
                    scheduler.execute(() -> notFound(eventType, rest));
                }
                return Disposition.LAST_RESORT;
            }
            BehaviourCandidate best = candidates.get(0);
            scheduler.execute(() -> install(eventType, searching, best));
            return Disposition.HOLD;
        }
        Promise<List<BehaviourCandidate>> answer = found;
        answer.onResolve(() -> scheduler.execute(() -> searched(eventType, searching, answer)));
        return Disposition.HOLD;
    }

    // ---------------------------------------------------------------- the BMS's thread

    /**
     * A bundle stopped or was uninstalled (the framework's bundle event, queued here): if it is a behaviour the
     * installer installed, {@link Revivals} brings it back after {@code restart.grace.ms}.
     */
    void wentAway(String symbolicName, long bundleId) {
        revivals.wentAway(symbolicName, bundleId);
    }

    private void searched(String eventType, Searching searching, Promise<List<BehaviourCandidate>> answer) {
        if (states.get(eventType) != searching) {
            return;
        }
        Throwable failure = Answers.failure(answer);
        if (failure != null) {
            failed(eventType, searching, null, Problem.DOWNLOAD_FAILED,
                    "searching the repositories failed: " + failure.getMessage());
            return;
        }
        List<BehaviourCandidate> candidates = Answers.value(answer);
        if (candidates == null || candidates.isEmpty()) {
            Resting rest = resting(searching, Rest.NOT_FOUND, null,
                    "no repository has a behaviour that consumes it (searched " + searching.searched() + ")");
            if (states.replace(eventType, searching, rest)) {
                notFound(eventType, rest);
            }
            return;
        }
        install(eventType, searching, candidates.get(0));
    }

    private void notFound(String eventType, Resting rest) {
        int discarded = discard(eventType, rest.reason());
        counters.notFound.increment();
        history.add(History.entry(scheduler.now(), "NOT_FOUND", List.of(eventType), null,
                scheduler.now() - rest.since(), 0, discarded, rest.reason()));
        alerts.notFound(eventType, rest.searched(), discarded, rest.until());
        if (loggedNotFound.add(eventType)) {
            log.warn("No repository offers a behaviour that consumes {} (searched {}); its events are counted as "
                    + "unhandled (bus:stats) and the repositories are not searched again for it for {} ms "
                    + "(negative.cache.ms, PID {}). {} held events given up on. Add a behaviour for it to a "
                    + "repository, or list the type in ignored.types.", eventType, rest.searched(),
                    settings.negativeCacheMs(), BehaviourManagerComponent.PID, discarded);
        }
    }

    /** Ask for the best candidate, or join the request in flight for the same behaviour. */
    private void install(String eventType, TypeState expected, BehaviourCandidate best) {
        if (states.get(eventType) != expected) {
            return;
        }
        int attempt = expected instanceof Searching s ? s.attempt() : 1;
        InstallJob job = jobs.inFlight(best.symbolicName);
        if (job == null) {
            // installed already but not taking events: stopped (a failure, Gogo's stop), a component not satisfied,
            // or its bundle uninstalled behind the installer's back. The same request starts or installs it again.
            String state = installer.installed().stream().filter(b -> best.symbolicName.equals(b.symbolicName))
                    .map(b -> b.state).findFirst().orElse(null);
            String kind = state == null ? "INSTALLED" : "UNINSTALLED".equals(state) ? "REINSTALLED" : "RESTARTED";
            String reason = "an event of type " + eventType + " had no consumer" + switch (kind) {
            case "RESTARTED" -> " and " + best.symbolicName + " is installed but not taking events (" + state
                    + "): started again";
            case "REINSTALLED" -> " and the bundle of " + best.symbolicName + " had been uninstalled (not with"
                    + " bis:uninstall): installed again";
            default -> "";
            } + " (Behaviour Management Service)";
            job = jobs.start(best.symbolicName, best.version, best.node, expected.searched(), kind, reason, false,
                    this::answered);
        }
        Installing installing = new Installing(expected.searched(), expected.since(), job.behaviour(), attempt,
                job.id());
        if (states.replace(eventType, expected, installing)) {
            job.types().add(eventType);
        }
    }

    private void answered(InstallJob job, Promise<InstalledBehaviour> answer) {
        long now = scheduler.now();
        List<String> types = new ArrayList<>();
        List<Installing> waiting = new ArrayList<>();
        for (String type : job.types()) {
            if (states.get(type) instanceof Installing i && i.job() == job.id()) {
                types.add(type);
                waiting.add(i);
            }
        }
        if (job.revival()) {
            revivals.answered(job, answer, !types.isEmpty()); // events waited for it too: their outcome is recorded
            if (types.isEmpty()) {
                return;
            }
        }
        Throwable failure = Answers.failure(answer);
        if (failure == null) {
            InstalledBehaviour done = Answers.value(answer);
            counters.installs.increment();
            long duration = 0;
            int attempt = 1;
            for (int k = 0; k < types.size(); k++) {
                Installing i = waiting.get(k);
                String type = types.get(k);
                Installed installed = new Installed(i.searched(), i.since(), job.behaviour(),
                        now + settings.handoverGraceMs());
                if (states.replace(type, i, installed)) {
                    // at the end of the grace period, not at the next sweep: events still held then are decided at once
                    scheduler.schedule(() -> graceEnded(type, installed), settings.handoverGraceMs());
                }
                duration = Math.max(duration, now - i.since());
                attempt = Math.max(attempt, i.attempt());
                history.add(History.entry(now, job.kind(), List.of(types.get(k)), job.behaviour(), now - i.since(),
                        i.attempt(), 0, job.kind().equals("INSTALLED") ? null : job.reason()));
            }
            if (!types.isEmpty()) {
                alerts.installed(types, done.symbolicName, done.version, done.repository, duration, attempt);
                log.info("{} {} for events of {} in {} ms (attempt {})", job.kind().equals("INSTALLED") ? "Installed"
                        : job.kind().equals("RESTARTED") ? "Started again" : "Installed again", job.behaviour(), types,
                        duration, attempt);
            }
            return;
        }
        counters.installFailures.increment();
        Problem problem = failure instanceof InstallException ie ? ie.problem() : Problem.START_FAILED;
        String reason = failure.getMessage() == null ? failure.toString() : failure.getMessage();
        for (int k = 0; k < types.size(); k++) {
            failed(types.get(k), waiting.get(k), job.behaviour(), problem, reason);
        }
    }

    /** An attempt for {@code eventType} failed: rest, or wait and retry with backoff, or give up at the deadline. */
    private void failed(String eventType, TypeState state, String behaviour, Problem problem, String reason) {
        long now = scheduler.now();
        int attempt = state.attempt();
        String what = behaviour == null ? "a behaviour" : behaviour;
        switch (problem) {
        case REMOVED_BY_OPERATOR -> {
            Resting rest = resting(state, Rest.REMOVED_BY_OPERATOR, behaviour, reason);
            if (states.replace(eventType, state, rest)) {
                int discarded = discard(eventType, "an operator removed or stopped " + what + "; not installed or"
                        + " started again until an operator allows it (bis:allow) or installs it (bis:install)");
                history.add(History.entry(now, "REMOVED_BY_OPERATOR", List.of(eventType), behaviour,
                        now - state.since(), attempt, discarded, reason));
                alerts.installFailed(eventType, behaviour, problem.name(), reason, attempt, 0, discarded);
                log.info("Not installing or starting {} for events of {}: an operator removed or stopped it; {} held"
                        + " events given up on, its events are counted as unhandled", what, eventType, discarded);
            }
        }
        case NOT_FOUND -> {
            Resting rest = resting(state, Rest.NOT_FOUND, behaviour, reason);
            if (states.replace(eventType, state, rest)) {
                notFound(eventType, rest);
            }
        }
        // a bundle whose bytes do not match its index (tampered or corrupted) does not fix itself: no retry
        case HASH_MISMATCH -> giveUp(eventType, state, behaviour, problem, reason);
        default -> {
            long delay = settings.backoff(attempt);
            long deadline = state.since() + settings.installDeadlineMs();
            history.add(History.entry(now, "INSTALL_FAILED", List.of(eventType), behaviour, now - state.since(),
                    attempt, heldCount(eventType), problem + ": " + reason));
            if (now + delay >= deadline) {
                giveUp(eventType, state, behaviour, problem, reason);
                return;
            }
            RetryWait wait = new RetryWait(state.searched(), state.since(), behaviour, attempt, now + delay,
                    problem + ": " + reason);
            if (states.replace(eventType, state, wait)) {
                int heldNow = heldCount(eventType);
                alerts.installFailed(eventType, behaviour, problem.name(), reason, attempt, wait.nextRetry(), heldNow);
                log.warn("Installing {} for events of {} failed (attempt {}, {}): {}. {} events held; next attempt in "
                        + "{} ms, giving up {} ms after the first event (install.deadline.ms).", what, eventType,
                        attempt, problem, reason, heldNow, delay, settings.installDeadlineMs());
                scheduler.schedule(() -> retry(eventType, wait), delay);
            }
        }
        }
    }

    private void retry(String eventType, RetryWait wait) {
        Searching again = new Searching(wait.searched(), wait.since(), wait.attempt() + 1);
        if (states.replace(eventType, wait, again)) {
            search(eventType, again); // the repositories may have changed: choose again
        }
    }

    private void giveUp(String eventType, TypeState state, String behaviour, Problem problem, String reason) {
        long now = scheduler.now();
        int attempt = state.attempt();
        Resting rest = resting(state, Rest.GAVE_UP, behaviour, reason);
        if (!states.replace(eventType, state, rest)) {
            return;
        }
        String what = behaviour == null ? "a behaviour" : behaviour;
        String why = problem == Problem.HASH_MISMATCH
                ? "a bundle of " + what + " does not match its index, so it is not installed nor tried again (a"
                        + " tampered or corrupted bundle does not fix itself): " + reason
                : "installing " + what + " kept failing for " + (now - state.since()) + " ms (install.deadline.ms "
                        + settings.installDeadlineMs() + "): " + reason;
        int discarded = discard(eventType, why);
        history.add(History.entry(now, "GAVE_UP", List.of(eventType), behaviour, now - state.since(), attempt,
                discarded, reason));
        alerts.installFailed(eventType, behaviour, problem == null ? "TIMEOUT" : problem.name(), reason, attempt, 0,
                discarded);
        log.error("Gave up installing {} for events of {} after {} attempt(s): {}. {} held events discarded (counted "
                + "as unhandled, bus:stats); its events are counted as unhandled for {} ms, then the next one tries "
                + "again. Fix the repository or the behaviour, or install it by hand (bis:install).",
                behaviour == null ? "a behaviour" : behaviour, eventType, attempt, why, discarded,
                settings.negativeCacheMs());
    }

    /**
     * Every {@code sweep.interval.ms}: held events of a type nothing works on (the BMS restarted, or an event held
     * in a race with a state change) get a search or are given up on; episodes past the deadline give up; states
     * that no longer matter are dropped.
     */
    void sweep() {
        long now = scheduler.now();
        Map<String, HeldType> heldNow = new HashMap<>();
        for (HeldType h : held.held()) {
            heldNow.put(h.eventType, h);
        }
        for (HeldType h : heldNow.values()) {
            TypeState state = states.get(h.eventType);
            if (state == null || (state instanceof Resting r && now >= r.until())) {
                // the deadline counts from now: the events were held before this BMS took them over
                Searching searching = new Searching(searchedTypes.hierarchy(h.eventType),
                        now, 1);
                if (state == null ? states.putIfAbsent(h.eventType, searching) == null
                        : states.replace(h.eventType, state, searching)) {
                    search(h.eventType, searching);
                }
            } else if (state instanceof Resting r) {
                counters.discarded.add(held.discard(h.eventType, r.reason()));
            } else if (state instanceof Installed i && now >= i.graceUntil()) {
                afterGrace(h.eventType, i);
            }
        }
        for (Map.Entry<String, TypeState> e : states.entrySet()) {
            TypeState state = e.getValue();
            boolean working = state instanceof Searching || state instanceof Installing;
            if (working && now >= state.since() + settings.installDeadlineMs()) {
                String behaviour = state instanceof Installing i ? i.behaviour() : null;
                giveUp(e.getKey(), state, behaviour, null, noAnswer(behaviour));
            } else if (state instanceof Installed i && now >= i.graceUntil() && !heldNow.containsKey(e.getKey())) {
                forget(e.getKey(), state); // handed over; a later unhandled event starts afresh anyway
            } else if (state instanceof Resting r && now >= r.until() && !heldNow.containsKey(e.getKey())) {
                forget(e.getKey(), state);
            }
        }
    }

    /** "no answer from the installer", and what the installer says it is doing (for that behaviour, if it says). */
    private String noAnswer(String behaviour) {
        List<String> doing;
        try {
            doing = installer.activities();
        } catch (RuntimeException e) {
            doing = List.of();
        }
        String name = behaviour == null ? null : behaviour.split(" ", 2)[0];
        List<String> mine = name == null ? List.of() : doing.stream().filter(a -> a.contains(name)).toList();
        return "no answer from the installer"
                + (doing.isEmpty() ? "" : "; it is " + String.join("; ", mine.isEmpty() ? doing : mine));
    }

    private void graceEnded(String eventType, Installed installed) {
        if (states.get(eventType) == installed && heldCount(eventType) > 0) {
            afterGrace(eventType, installed);
        }
    }

    /** Events still held after the hand-over: the behaviour does not take them, or it went away already. */
    private void afterGrace(String eventType, Installed installed) {
        boolean active = installer.installed().stream().anyMatch(b -> "ACTIVE".equals(b.state)
                && installed.behaviour().equals(b.symbolicName + " " + b.version));
        if (!active) {
            Searching again = new Searching(installed.searched(), scheduler.now(), 1);
            if (states.replace(eventType, installed, again)) {
                search(eventType, again); // it went away by itself: bring it back
            }
            return;
        }
        String reason = installed.behaviour() + " is installed and active but does not take these events (its "
                + "filter)";
        Resting rest = resting(installed, Rest.NOT_TAKEN, installed.behaviour(), reason);
        if (states.replace(eventType, installed, rest)) {
            int discarded = discard(eventType, reason);
            history.add(History.entry(scheduler.now(), "NOT_TAKEN", List.of(eventType), installed.behaviour(), 0, 0,
                    discarded, reason));
        }
    }

    // ---------------------------------------------------------------- helpers

    /** Drop a state that no longer matters, and the type's hierarchy with it: the maps stay as small as the work. */
    private void forget(String eventType, TypeState state) {
        if (states.remove(eventType, state)) {
            searchedTypes.forget(eventType);
        }
    }

    private Resting resting(TypeState from, Rest kind, String behaviour, String reason) {
        return new Resting(from.searched(), from.since(), kind, behaviour,
                scheduler.now() + settings.negativeCacheMs(), reason, new LongAdder());
    }

    private int discard(String eventType, String reason) {
        int n = held.discard(eventType, reason);
        counters.discarded.add(n);
        return n;
    }

    private int heldCount(String eventType) {
        return held.held().stream().filter(h -> h.eventType.equals(eventType)).mapToInt(h -> h.count).findFirst()
                .orElse(0);
    }

    // ---------------------------------------------------------------- monitoring (any thread)

    Map<String, TypeState> states() {
        return Map.copyOf(states);
    }

    List<HistoryEntry> history() {
        return history.entries();
    }

    List<HeldType> heldNow() {
        return held.held();
    }
}
